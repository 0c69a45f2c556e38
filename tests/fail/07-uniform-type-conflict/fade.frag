#version 330 core
in float vFade;

uniform vec2 fade;

out vec4 FragColor;

void main()
{
    FragColor = vec4(vFade * fade.x, fade.y, 0.0, 1.0);
}
