#version 400
// Sampler arrays indexed at run time (dynamically uniform indices, legal since GLSL 4.00):
// a loop over the elements, an index computed from a texture's size, and an array of
// structs with a sampler member.
in vec2 uv;
out vec4 color;

uniform sampler2D tex[3];

struct Layer {
    sampler2D map;
    float weight;
};
uniform Layer layers[2];

void main()
{
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 3; i++) {
        sum += textureLod(tex[i], uv * float(i + 1), float(i)) / 3.0;
    }
    int k = textureSize(tex[0], 0).x / 512;  // 1 for the 512x512 placeholder
    vec4 picked = texture(layers[k].map, uv.yx) + texelFetch(tex[k + 1], ivec2(uv * 64.0), 0);
    ivec2 size = textureSize(tex[2 - k], 1);
    color = vec4(sum.rg, picked.b * 0.5, float(size.x) / 256.0);
}
