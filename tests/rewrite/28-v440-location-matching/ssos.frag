#version 440 core
layout(location = 0) in vec2 inUV;
layout(location = 1) in Other { vec4 col; } fIn;
layout(location = 0) out vec4 c;
void main() { c = vec4(inUV, 0.0, 1.0) + fIn.col; }
