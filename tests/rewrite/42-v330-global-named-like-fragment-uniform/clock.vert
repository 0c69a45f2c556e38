#version 330 core
layout(location = 0) in vec2 aPos;
float time = 0.0;
out float vTime;
void main()
{
    time += aPos.x;
    vTime = time;
    gl_Position = vec4(aPos, 0.0, 1.0);
}
