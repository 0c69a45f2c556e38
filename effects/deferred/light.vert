#version 330 core
// Deferred renderer, light pass (seed 001): one fullscreen triangle per point light
// (instanced), each accumulated additively into the light buffer. The vertex stage works
// out where this instance's light is at the current time (the same path as lamps.vert)
// and hands it to the fragment stage.

layout(location = 0) in vec3 position;
layout(location = 1) in vec2 texCoord;
layout(location = 2) in vec3 lightColour;   // per instance
layout(location = 3) in float lightPhase;   // per instance
layout(location = 4) in float lightOrbit;   // per instance

uniform float time;
uniform float lightSpeed;
uniform float lightHeight;

out Vertex {
    vec2 texCoord;
} OUT;

// Per-light values, the same at every vertex of this instance. (Declared outside the
// block: naga rejects `flat` on block members.)
flat out vec3 vLightPos;
flat out vec3 vLightColour;

vec3 lightPosition(float phase, float orbit)
{
    float a = time * lightSpeed * (1.0 + 0.15 * phase) + phase;
    return vec3(cos(a) * orbit,
                lightHeight + 0.3 * sin(a * 2.0 + phase),
                sin(a) * orbit);
}

void main(void)
{
    OUT.texCoord = texCoord;
    vLightPos = lightPosition(lightPhase, lightOrbit);
    vLightColour = lightColour;
    gl_Position = vec4(position.xy, 0.0, 1.0);
}
