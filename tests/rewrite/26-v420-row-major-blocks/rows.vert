#version 420 core
layout(location = 0) in vec3 pos;
layout(row_major) uniform B { mat4 m; } b;
layout(std140, row_major) uniform C { mat4 n; } c;
layout(binding = 2, row_major) uniform D { mat4 o; } d;
void main() { gl_Position = b.m * c.n * d.o * vec4(pos, 1.0); }
