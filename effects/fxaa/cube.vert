#version 330 core
// FXAA test scene (seed 001, FXAA post process): a spinning cube whose faces get flat,
// high-contrast colours; the vertex stage hands on the object-space normal and the uv.

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexCoord;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

out Vertex
{
    vec3 objectNormal;
    vec2 texCoord;
} OUT;

void main(void)
{
    OUT.objectNormal = aNormal;
    OUT.texCoord = aTexCoord;
    gl_Position = projection * view * model * vec4(aPosition, 1.0);
}
