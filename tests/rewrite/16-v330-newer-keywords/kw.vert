#version 330 core
layout(location = 0) in vec2 aPos;

out vec2 sample;

void main()
{
    float buffer = 0.5;
    sample = aPos * buffer + buffer;
    gl_Position = vec4(aPos, 0.0, 1.0);
}
