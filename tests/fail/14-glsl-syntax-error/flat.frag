#version 330 core
out vec4 FragColor;

uniform vec3 color;

void main()
{
    vec3 c = color * 0.5
    FragColor = vec4(c, 1.0);
}
