#version 330 core
// Deferred renderer, G-buffer pass 1 (seed 001): the terrain around the lake.
// A plane_grid is displaced into a basin (the lake bed) ringed by hills; the normal is
// taken from finite differences of the same height function. World position goes to the
// fragment stage for the G-buffer position target and the height-based glow.

layout(location = 0) in vec3 position;
layout(location = 1) in vec2 texCoord;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform float basinDepth;   // how far the lake bed sinks below y = 0
uniform float hillHeight;   // height of the hills around the lake

out Vertex {
    vec2 texCoord;
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
    vec3 flatPos = (model * vec4(position, 1.0)).xyz;
    vec2 p = flatPos.xz;
    float h = terrainHeight(p);

    const float e = 0.02;
    float hx = terrainHeight(p + vec2(e, 0.0)) - terrainHeight(p - vec2(e, 0.0));
    float hz = terrainHeight(p + vec2(0.0, e)) - terrainHeight(p - vec2(0.0, e));
    OUT.normal = normalize(vec3(-hx, 2.0 * e, -hz));

    vec3 worldPos = vec3(p.x, flatPos.y + h, p.y);
    OUT.worldPos = worldPos;
    OUT.texCoord = texCoord;
    gl_Position = projection * view * vec4(worldPos, 1.0);
}
