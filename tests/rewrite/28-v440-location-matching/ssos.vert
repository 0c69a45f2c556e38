#version 440 core
layout(location = 0) in vec2 p;
layout(location = 0) out vec2 outUV;
layout(location = 1) out Block { vec4 color; } vOut;
void main() { outUV = p; vOut.color = vec4(1.0); gl_Position = vec4(p, 0.0, 1.0); }
