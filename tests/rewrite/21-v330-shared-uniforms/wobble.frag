#version 330 core
in float vWave;

uniform float time;
uniform vec3 color;

out vec4 fragColor;

void main()
{
    fragColor = vec4(color * (0.75 + 0.25 * sin(time)) + vWave, 1.0);
}
