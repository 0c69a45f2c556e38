#version 410 core
layout(location = 1) in vec2 vUv;

layout(location = 0) out vec4 fragColor;

void main()
{
    fragColor = vec4(vUv, 0.0, 1.0);
}
