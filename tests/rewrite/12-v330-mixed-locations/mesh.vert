#version 330 core
layout(location = 0) in vec3 aPos;
in vec3 aNormal;
layout(location = 2) in vec2 aUv;
in vec4 aColor;

out vec3 vNormal;
out vec2 vUv;
out vec4 vColor;

void main()
{
    vNormal = aNormal;
    vUv = aUv;
    vColor = aColor;
    gl_Position = vec4(aPos, 1.0);
}
