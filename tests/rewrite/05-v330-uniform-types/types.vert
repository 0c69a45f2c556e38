#version 330 core
layout(location = 0) in vec3 aPos;

uniform mat4 model;
uniform mat3 normalMat;
uniform mat2 rot2;

out vec3 vPos;

void main()
{
    vec3 p = normalMat * aPos;
    p.xy = rot2 * p.xy;
    vPos = p;
    gl_Position = model * vec4(p, 1.0);
}
