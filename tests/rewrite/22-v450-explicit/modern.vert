#version 450 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec2 aUv;

layout(std140, binding = 0) uniform Camera {
    mat4 view;
    mat4 proj;
} camera;

layout(location = 0) out vec2 vUv;

void main()
{
    vUv = aUv;
    gl_Position = camera.proj * camera.view * vec4(aPos, 1.0);
}
