#version 330 core
#extension GL_GOOGLE_include_directive : require
#include "lighting/lambert.glsl"
#include "lighting/lambert.glsl"
in vec3 normal;
uniform vec3 lightDir;
out vec4 color;
void main()
{
    color = vec4(vec3(lambert(normal, lightDir)), 1.0);
}
