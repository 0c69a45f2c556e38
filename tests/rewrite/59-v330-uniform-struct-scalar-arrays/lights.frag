#version 330
// Arrays of scalars and 2-vectors inside structs that only uniforms use: std140 strides their
// elements 16 bytes apart, which WGSL's uniform rules refuse for an i32, f32 or vec2 array.
struct Light {
    vec4 colour;
    int enabled[2];
    float falloff[3];
    vec2 offsets[2];
};
struct Band {
    float weights[4];
};
uniform Light lights[2];
layout(std140) uniform Bands {
    Band band;
};
in vec2 uv;
out vec4 colour;

void main()
{
    vec3 sum = vec3(0.0);
    for (int i = 0; i < 2; i++) {
        if (lights[i].enabled[1] != 0 || lights[i].enabled[0] == 0) {
            float d = length(uv - lights[i].offsets[i]);
            sum += lights[i].colour.rgb * (1.0 - d * lights[i].falloff[2]) + vec3(band.weights[i + 1]);
        }
    }
    colour = vec4(sum, 1.0);
}
