#version 330 core
in vec3 vPos;

uniform bool enabled;
uniform int mode;
uniform uint flags;
uniform float gain;
uniform vec2 offset;
uniform vec3 tint;
uniform vec4 base;
uniform ivec2 cells;
uniform ivec3 steps;
uniform ivec4 mask;
uniform float weights[4];
uniform vec2 taps[3];
uniform bool toggles[2];
uniform mat2 warps[2];

out vec4 fragColor;

void main()
{
    vec4 c = base;
    if (enabled)
        c.rgb *= tint * gain;
    if (mode == 1 && (flags & 1u) != 0u)
        c.rg += offset;
    float w = weights[0] + weights[1] + weights[2] + weights[3];
    vec2 t = taps[0] + taps[1] + taps[2];
    if (toggles[0] || toggles[1])
        t = warps[0] * t + warps[1] * t;
    c.rgb += vec3(cells, steps.z + mask.w) * 0.001 * w + vec3(t, 0.0) + vPos * 0.0;
    fragColor = c;
}
