#version 330 core
in vec3 ourColor;

uniform float brightness;

out vec4 FragColor;

void main()
{
    FragColor = vec4(ourColor * brightness, 1.0);
}
