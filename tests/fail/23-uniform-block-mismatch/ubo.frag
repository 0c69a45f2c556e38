#version 330 core
layout(std140) uniform Matrices {
    mat4 view;
    mat4 projection;
};

out vec4 FragColor;

void main()
{
    FragColor = vec4(view[3].xyz * 0.1, 1.0);
}
