#version 440 core
layout(location = 0) in vec3 inColor;
layout(location = 0, component = 3) in float inAlpha;
out vec4 FragColor;
void main()
{
    FragColor = vec4(inColor, inAlpha);
}
