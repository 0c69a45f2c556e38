#version 330 core
// Deferred renderer, transparent pass (seed 001): transparent green water with subtle
// environment mapping of the sky (the reflected ray looks up the same gradient the sky
// dome shows), ripples from a few moving sine waves, and a Fresnel term. Not lit by the
// deferred lights, as in the seed.

uniform vec3 cameraPos;
uniform float time;
uniform vec3 waterColour;
uniform float waterAlpha;       // opacity looking straight down
uniform float reflectivity;     // strength of the sky reflection
uniform float waveAmplitude;    // ripple slope
uniform float waveFrequency;    // ripple radians per world unit
uniform float waveSpeed;        // ripple radians per second
uniform vec3 skyHorizon;
uniform vec3 skyZenith;

in Vertex {
    vec2 texCoord;
    vec3 worldPos;
} IN;

out vec4 fragColour;

// A phase wrapped to [0, 2pi) before sin/cos (W0717): time * speed grows without bound, and
// after hours f32 keeps too few digits of it. fract(x / TWO_PI) * TWO_PI is mod(x, TWO_PI).
const float TWO_PI = 6.2831853;
float wrapPhase(float x)
{
    return fract(x / TWO_PI) * TWO_PI;
}

vec3 safeNormalize(vec3 v)
{
    return v * inversesqrt(max(dot(v, v), 1e-12));
}

vec3 skyColour(vec3 dir)
{
    float up = clamp(dir.y, -1.0, 1.0);
    vec3 colour = mix(skyHorizon, skyZenith, smoothstep(0.0, 0.7, up));
    return mix(colour, skyHorizon * 0.35, smoothstep(0.0, -0.3, up));
}

void main(void)
{
    vec2 p = IN.worldPos.xz * waveFrequency;
    float t = time * waveSpeed;
    vec2 slope = vec2(cos(p.x + wrapPhase(t)) + 0.5 * cos(p.x * 0.7 + p.y * 1.3 + wrapPhase(t * 1.3)),
                      cos(p.y * 1.1 - wrapPhase(t * 0.8)) + 0.5 * cos(p.y * 0.6 - p.x * 1.2 + wrapPhase(t * 0.7)));
    vec3 N = safeNormalize(vec3(-slope.x * waveAmplitude, 1.0, -slope.y * waveAmplitude));

    vec3 I = safeNormalize(IN.worldPos - cameraPos);
    vec3 R = reflect(I, N);
    vec3 env = skyColour(R);

    float cosTheta = clamp(dot(-I, N), 0.0, 1.0);
    float fresnel = clamp(reflectivity + (1.0 - reflectivity) * pow(1.0 - cosTheta, 5.0), 0.0, 1.0);

    vec3 colour = mix(waterColour, env, fresnel);
    float alpha = clamp(mix(waterAlpha, 1.0, fresnel), 0.0, 1.0);
    fragColour = vec4(colour, alpha);
}
