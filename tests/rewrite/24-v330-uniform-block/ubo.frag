#version 330 core
layout(std140) uniform Matrices {
    mat4 projection;
    mat4 view;
} matrices;

out vec4 FragColor;

void main()
{
    FragColor = vec4(normalize(matrices.view[2].xyz) * 0.5 + 0.5, 1.0);
}
