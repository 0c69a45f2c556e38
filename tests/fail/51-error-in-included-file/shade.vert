#version 330 core
in vec3 pos;
out vec3 normal;
void main() { normal = pos; gl_Position = vec4(pos, 1.0); }
