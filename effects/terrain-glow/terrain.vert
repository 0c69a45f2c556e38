#version 330 core
// Terrain (seed 001): a plane_grid displaced upwards by a height read from a noise texture
// in the vertex stage; the normal comes from central differences of the same height map.

layout(location = 0) in vec3 aPosition; // plane_grid: xz in -0.5..0.5, y = 0
layout(location = 1) in vec2 aTexCoord; // u along +x, v along -z

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform sampler2D heightMap;
uniform float terrainSize;    // world units per side
uniform float heightScale;    // world height of a normalised height of 1
uniform float heightContrast; // stretches the noise (which clusters around 0.5)
uniform float waterLevel;     // normalised height of the flat lake surface

out Vertex
{
    float height;     // normalised terrain height (0..1), before the lake is flattened
    vec3 worldNormal;
    vec3 worldPos;
} OUT;

float terrainHeight(vec2 uv)
{
    float n = texture(heightMap, uv).r;
    return clamp((n - 0.5) * heightContrast + 0.5, 0.0, 1.0);
}

void main()
{
    float h = terrainHeight(aTexCoord);
    float surface = max(h, waterLevel); // the lake is flat

    // Central differences (one texel) for the slope; the lake neighbours are flattened too.
    float e = 1.0 / 256.0;
    float hl = max(terrainHeight(aTexCoord - vec2(e, 0.0)), waterLevel);
    float hr = max(terrainHeight(aTexCoord + vec2(e, 0.0)), waterLevel);
    float hd = max(terrainHeight(aTexCoord - vec2(0.0, e)), waterLevel);
    float hu = max(terrainHeight(aTexCoord + vec2(0.0, e)), waterLevel);
    float worldStep = 2.0 * e * terrainSize; // never zero: terrainSize > 0 (range [0.5, 10])
    float dydx = (hr - hl) * heightScale / max(worldStep, 1e-4);
    float dydz = -(hu - hd) * heightScale / max(worldStep, 1e-4); // v runs along -z
    vec3 objectNormal = normalize(vec3(-dydx, 1.0, -dydz)); // y = 1: never zero length

    vec3 p = vec3(aPosition.x * terrainSize, surface * heightScale, aPosition.z * terrainSize);
    vec4 world = model * vec4(p, 1.0);

    OUT.height = h;
    OUT.worldNormal = mat3(model) * objectNormal; // model: rotation only
    OUT.worldPos = world.xyz;
    gl_Position = projection * view * world;
}
