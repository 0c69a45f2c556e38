#version 330 core
#extension GL_GOOGLE_include_directive : require
#include "shade.glsl"
in vec3 normal;
out vec4 color;
void main() { color = vec4(shade(normal)); }
