#version 330 core
layout(location = 0) in vec3 aPos;

struct Light {
    mat4 transform;
};

uniform Light shadowCaster;

out vec4 vShadowPos;

void main()
{
    vShadowPos = shadowCaster.transform * vec4(aPos, 1.0);
    gl_Position = vec4(aPos, 1.0);
}
