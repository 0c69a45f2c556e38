#version 330 core
// Environment-mapped object, vertex stage (seed 000): world-space position and normal
// for the fragment stage, which reflects the view ray into the skybox's cube map.

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

out vec3 worldPos;
out vec3 worldNormal;

void main()
{
    vec4 wp = model * vec4(position, 1.0);
    worldPos = wp.xyz;
    // Rotation with uniform scale: mat3(model) keeps normals perpendicular.
    worldNormal = mat3(model) * normal;
    gl_Position = projection * view * wp;
}
