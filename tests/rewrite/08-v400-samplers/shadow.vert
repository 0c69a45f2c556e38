#version 400
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;

uniform mat4 mvp;
uniform mat4 lightSpace;

out vec4 vLightPos;
out vec3 vNormal;

void main()
{
    vLightPos = lightSpace * vec4(aPos, 1.0);
    vNormal = aNormal;
    gl_Position = mvp * vec4(aPos, 1.0);
}
