#version 330 core
layout(location = 0) in vec3 aPos;

uniform mat3 model;
uniform mat4 viewProj;

void main()
{
    gl_Position = viewProj * vec4(model * aPos, 1.0);
}
