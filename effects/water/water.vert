#version 330 core
// Water surface (seed 001): the whole lake rises and falls with sin(time), with travelling
// ripples on top. The normal is rebuilt from the analytic derivative of the height.

layout(location = 0) in vec3 aPos;
layout(location = 1) in vec2 aTexCoord;

out vec3 WorldPos;
out vec3 WorldNormal;
out vec2 TexCoord;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform float time;
uniform float levelAmplitude;
uniform float levelSpeed;
uniform float waveAmplitude;
uniform float waveFrequency;
uniform float waveSpeed;

const float TWO_PI = 6.2831853;

void main()
{
    vec4 worldPos = model * vec4(aPos, 1.0);
    float x = worldPos.x;
    float z = worldPos.z;

    // Height field h(x, z, t) = level(t) + two crossing ripples.
    // wrapped to [0, 2pi) before sin/cos (W0717): a phase that grows with time loses f32
    // precision after hours. Each time term is wrapped (fract(x / TWO_PI) * TWO_PI is
    // mod(x, TWO_PI)), so p1, p2 and the level phase stay bounded.
    float p1 = (x + 0.6 * z) * waveFrequency + fract(time * waveSpeed / TWO_PI) * TWO_PI;
    float p2 = (z - 0.4 * x) * waveFrequency * 1.3 - fract(time * waveSpeed * 0.8 / TWO_PI) * TWO_PI;
    float level = levelAmplitude * sin(fract(time * levelSpeed / TWO_PI) * TWO_PI);
    float h = level + waveAmplitude * (sin(p1) + 0.5 * sin(p2));

    // Partial derivatives of h.
    float dhdx = waveAmplitude * waveFrequency * (cos(p1) - 0.5 * 0.4 * 1.3 * cos(p2));
    float dhdz = waveAmplitude * waveFrequency * (0.6 * cos(p1) + 0.5 * 1.3 * cos(p2));

    worldPos.y += h;
    WorldPos = worldPos.xyz;
    // Normal of y = h(x, z) is (-dh/dx, 1, -dh/dz); its y component is 1, so it is never zero.
    WorldNormal = vec3(-dhdx, 1.0, -dhdz);
    TexCoord = aTexCoord;
    gl_Position = projection * view * worldPos;
}
