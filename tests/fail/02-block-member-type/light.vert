#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;

out VS_OUT {
    vec3 normal;
    vec3 worldPos;
} vs_out;

uniform mat4 mvp;

void main()
{
    vs_out.normal = aNormal;
    vs_out.worldPos = aPos;
    gl_Position = mvp * vec4(aPos, 1.0);
}
