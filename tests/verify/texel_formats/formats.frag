#version 330
// Textures in the manifest's float and integer formats: values beyond [0, 1] and integers
// reach the program as the manifest gives them.
in vec2 uv;
out vec4 color;
uniform sampler2D hdr;     // rgba32f: red runs from -2 to 3
uniform sampler2D half16;  // rgba16f: red runs from 0 to 50
uniform usampler2D ids;    // r32ui: a checker of 7 and 1000
uniform isampler2D signs;  // rgba32i: one texel (-5, 3, 2^24 + 1, 1)
void main()
{
    float h = texture(hdr, uv).r;
    float g = texture(half16, uv).r;
    uint id = texture(ids, uv).r;
    ivec4 s = texelFetch(signs, ivec2(0, 0), 0);
    color = vec4((h + 2.0) / 5.0, g / 50.0, float(id) / 1000.0, float(s.x + 5 + s.y + int(s.z == 16777217)) / 8.0);
}
