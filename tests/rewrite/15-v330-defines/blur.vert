#version 330 core
#define FLIP_Y 1
layout(location = 0) in vec2 aPos;

out vec2 uv;

void main()
{
    uv = aPos * 0.5 + 0.5;
#ifdef FLIP_Y
    uv.y = 1.0 - uv.y;
#endif
    gl_Position = vec4(aPos, 0.0, 1.0);
}
