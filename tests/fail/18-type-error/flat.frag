#version 330 core
out vec4 FragColor;

void main()
{
    float x = vec3(1.0);
    FragColor = vec4(x, 0.5, 0.2, 1.0);
}
