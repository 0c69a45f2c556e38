#version 330 core
in vec2 uv;

uniform float exposure = 1.5;
uniform vec3 whitePoint = vec3(1.0, 1.0, 1.0);

out vec4 fragColor;

void main()
{
    vec3 c = vec3(uv, 0.5) * exposure;
    fragColor = vec4(c / (c + whitePoint), 1.0);
}
