#version 330 core
// Deferred renderer, transparent pass (seed 001): the lake surface, drawn forward after
// the combine onto the combined image. It rises and falls with sin(time) like the seed's
// water vertex shader.

layout(location = 0) in vec3 position;
layout(location = 1) in vec2 texCoord;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform float time;
uniform float waterLevel;
uniform float levelAmplitude;
uniform float levelSpeed;

out Vertex {
    vec2 texCoord;
    vec3 worldPos;
} OUT;

// A phase wrapped to [0, 2pi) before sin/cos (W0717): time * speed grows without bound, and
// after hours f32 keeps too few digits of it. fract(x / TWO_PI) * TWO_PI is mod(x, TWO_PI).
const float TWO_PI = 6.2831853;
float wrapPhase(float x)
{
    return fract(x / TWO_PI) * TWO_PI;
}

void main(void)
{
    vec4 worldPos = model * vec4(position, 1.0);
    worldPos.y += waterLevel + levelAmplitude * sin(wrapPhase(time * levelSpeed));
    OUT.texCoord = texCoord;
    OUT.worldPos = worldPos.xyz;
    gl_Position = projection * view * worldPos;
}
