#version 430
// textureGather takes this program through SPIR-V; the images have no format (GL: the bound
// image's), which naga's SPIR-V front would read as sampled textures.
uniform sampler2D heights;
layout(binding = 1) writeonly uniform image2D slopes;
layout(binding = 2) writeonly uniform iimage2D signs;
in vec2 uv;
out vec4 colour;

void main()
{
    vec4 h = textureGather(heights, uv);
    vec2 slope = vec2(h.y - h.x, h.w - h.x);
    ivec2 texel = ivec2(gl_FragCoord.xy);
    imageStore(slopes, texel, vec4(slope, 0.0, 1.0));
    imageStore(signs, texel, ivec4(sign(slope), 0, 1));
    colour = vec4(abs(slope), h.x, 1.0);
}
