#version 410 core
layout(location = 0) in vec2 inTint;
out vec4 FragColor;
void main()
{
    FragColor = vec4(inTint, 0.0, 1.0);
}
