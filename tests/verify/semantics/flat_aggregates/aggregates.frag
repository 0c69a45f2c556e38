#version 330 core
struct Tint { vec3 rgb; float weight; };
flat in Tint tint;
flat in vec2 pair[2];
centroid in float ramp[2];
in Tint smooth_tint;
out vec4 color;

void main()
{
    vec3 c = tint.rgb * tint.weight + vec3(pair[0] + pair[1], ramp[0]) * 0.5;
    color = vec4(c + smooth_tint.rgb * 0.25 * ramp[1], smooth_tint.weight);
}
