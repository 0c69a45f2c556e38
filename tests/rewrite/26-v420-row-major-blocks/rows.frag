#version 420 core
layout(location = 0, index = 0) out vec4 col;
void main() { col = vec4(1.0); }
