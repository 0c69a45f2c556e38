#version 330 core
uniform vec3 tint = vec3(1.0, 0.5, 0.2);

out vec4 FragColor;

void main()
{
    FragColor = vec4(tint, 1.0);
}
