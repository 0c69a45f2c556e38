#version 330 core
// Per-pixel Phong, vertex stage (seed 002): world-space position, normal and uv are
// interpolated; all lighting happens per pixel in the fragment stage.

layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexCoords;

out VS_OUT
{
    vec3 FragPos;
    vec3 Normal;
    vec2 TexCoords;
} vs_out;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

void main()
{
    vec4 worldPos = model * vec4(aPos, 1.0);
    vs_out.FragPos = worldPos.xyz;
    // Rotation + uniform scale only: mat3(model) transforms normals correctly.
    vs_out.Normal = mat3(model) * aNormal;
    vs_out.TexCoords = aTexCoords;
    gl_Position = projection * view * worldPos;
}
