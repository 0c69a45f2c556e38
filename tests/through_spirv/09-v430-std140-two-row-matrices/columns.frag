#version 430 core

struct Light {
    mat2 m;
    vec2 o;
};

layout(std140, binding = 1) uniform Params {
    mat2 rot;
    mat3x2 shear[2];
    int which;
    Light lights[2];
};

in vec2 uv;
out vec4 color;

void main()
{
    vec2 p = rot * (uv - 0.5);
    vec2 q = shear[which] * vec3(p, 1.0);
    Light l = lights[uv.x > 0.5 ? 1 : 0];
    vec2 c = shear[1 - which][which + 1] + l.m * l.o;
    color = vec4(q * 0.5 + 0.5, c.x * 0.5 + rot[1][0] * lights[0].m[1].y, 1.0);
}
