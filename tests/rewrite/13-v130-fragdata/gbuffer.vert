#version 130
in vec3 position;
in vec3 normal;

uniform mat4 mvp;

out vec3 vNormal;
out vec3 vPos;

void main()
{
    vNormal = normal;
    vPos = position;
    gl_Position = mvp * vec4(position, 1.0);
}
