#version 330 core
in vec4 vShadowPos;

struct Light {
    vec3 color;
    float power;
};

uniform Light light;
uniform float exposure;

out vec4 fragColor;

void main()
{
    fragColor = vec4(light.color * light.power * exposure + vShadowPos.xyz * 0.0, 1.0);
}
