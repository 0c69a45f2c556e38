#version 330 core
in vec3 LightingColor;
out vec4 FragColor;

void main()
{
    FragColor = vec4(LightingColor, 1.0);
}
