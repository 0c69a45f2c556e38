#version 330 core
// Environment mapping, vertex stage (seed 000): passes the world-space position and
// normal to the fragment stage, which reflects the view ray around the normal.

layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;

out vec3 WorldPos;
out vec3 WorldNormal;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

void main()
{
    vec4 worldPos = model * vec4(aPos, 1.0);
    WorldPos = worldPos.xyz;
    // The model matrix here is a rotation with uniform scale, so mat3(model) keeps
    // normals perpendicular (no inverse-transpose needed); the fragment stage renormalizes.
    WorldNormal = mat3(model) * aNormal;
    gl_Position = projection * view * worldPos;
}
