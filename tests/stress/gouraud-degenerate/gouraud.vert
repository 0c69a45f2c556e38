#version 330 core
// Gouraud shading as lighting tutorials write it: the light is computed per vertex, with
// the normal normalized in the vertex stage. A triangle of zero area brings a zero normal
// (its face normal, cross(b - a, c - a), is zero): normalize() divides 0 by 0 there, and
// as the triangle covers no pixel, no frame shows it.
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;

out vec3 LightingColor;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform vec3 lightPos;

void main()
{
    vec4 world = model * vec4(aPos, 1.0);
    gl_Position = projection * view * world;
    vec3 norm = normalize(mat3(model) * aNormal);
    vec3 lightDir = normalize(lightPos - world.xyz);
    float diff = max(dot(norm, lightDir), 0.0);
    LightingColor = vec3(0.1) + diff * vec3(0.9, 0.8, 0.7);
}
