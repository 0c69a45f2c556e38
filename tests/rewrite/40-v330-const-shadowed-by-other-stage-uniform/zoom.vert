#version 330 core
layout(location = 0) in vec2 aPos;

out vec2 uv;

const float scale = 0.5;

void main()
{
    uv = aPos * 0.5 + 0.5;
    gl_Position = vec4(aPos * scale, 0.0, 1.0);
}
