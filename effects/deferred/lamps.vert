#version 330 core
// Deferred renderer, G-buffer pass 3 (seed 001): small unlit emissive spheres that mark
// the moving point lights, instanced once per light. The light path here must match the
// one in light.vert (same per-instance phase / orbit, same uniforms).

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 lightColour;   // per instance
layout(location = 2) in float lightPhase;   // per instance
layout(location = 3) in float lightOrbit;   // per instance

uniform mat4 view;
uniform mat4 projection;
uniform float time;
uniform float lightSpeed;    // radians per second along the orbit
uniform float lightHeight;   // mean height of the lights
uniform float lampRadius;    // size of the marker spheres

out Vertex {
    vec3 colour;
    vec3 worldPos;
} OUT;

vec3 lightPosition(float phase, float orbit)
{
    float a = time * lightSpeed * (1.0 + 0.15 * phase) + phase;
    return vec3(cos(a) * orbit,
                lightHeight + 0.3 * sin(a * 2.0 + phase),
                sin(a) * orbit);
}

void main(void)
{
    vec3 worldPos = lightPosition(lightPhase, lightOrbit) + position * lampRadius;
    OUT.colour = lightColour;
    OUT.worldPos = worldPos;
    gl_Position = projection * view * vec4(worldPos, 1.0);
}
