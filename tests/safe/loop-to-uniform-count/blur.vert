#version 330 core
// Loops to a count the application sets (no manifest range): a counter compared with an
// int never passes INT_MAX, so no loop here can overflow its counter (W0719 must stay quiet).
layout(location = 0) in vec2 aPos;
out vec2 uv;

void main()
{
    uv = aPos * 0.5 + 0.5;
    gl_Position = vec4(aPos, 0.0, 1.0);
}
