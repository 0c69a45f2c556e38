#version 330 core
// Deferred renderer, G-buffer pass 4 (seed 001): a large sky dome (uv_sphere seen from
// inside). The sky is an unlit object in the G-buffer, like the seed's skybox.

layout(location = 0) in vec3 position;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

out Vertex {
    vec3 worldPos;
} OUT;

void main(void)
{
    vec4 worldPos = model * vec4(position, 1.0);
    OUT.worldPos = worldPos.xyz;
    gl_Position = projection * view * worldPos;
}
