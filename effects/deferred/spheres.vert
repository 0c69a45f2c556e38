#version 330 core
// Deferred renderer, G-buffer pass 2 (seed 001): lit spheres resting on the hills,
// drawn with GPU instancing (one uv_sphere, per-instance offset / radius / colour).
// Each sphere sits on the same terrain height function the terrain pass uses.

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 sphereOffset;   // per instance: x, z on the ground
layout(location = 3) in float sphereRadius;  // per instance
layout(location = 4) in vec3 sphereColour;   // per instance

uniform mat4 view;
uniform mat4 projection;
uniform float basinDepth;
uniform float hillHeight;

out Vertex {
    vec3 colour;
    vec3 normal;
    vec3 worldPos;
} OUT;

float terrainHeight(vec2 p)
{
    float r = length(p);
    float bowl = basinDepth * (1.0 - smoothstep(0.4, 2.6, r));
    float hills = hillHeight * smoothstep(2.0, 4.2, r)
                * (0.65 + 0.35 * sin(p.x * 1.7 + 0.5) * cos(p.y * 1.3 - 0.4));
    float bumps = 0.06 * sin(p.x * 4.1) * sin(p.y * 3.7);
    return hills - bowl + bumps;
}

void main(void)
{
    vec3 centre = vec3(sphereOffset.x,
                       terrainHeight(sphereOffset) + sphereRadius * 0.85,
                       sphereOffset.y);
    vec3 worldPos = centre + position * sphereRadius;
    OUT.colour = sphereColour;
    OUT.normal = normal;
    OUT.worldPos = worldPos;
    gl_Position = projection * view * vec4(worldPos, 1.0);
}
