#version 330 core
// Terrain colour by height, plus a glow (seed 001's "glow buffer", written straight into the
// colour here and not lit) on everything above glowThreshold, pulsing over time.

in Vertex
{
    float height;
    vec3 worldNormal;
    vec3 worldPos;
} IN;

out vec4 FragColor;

uniform float time;
uniform float waterLevel;
uniform float glowThreshold; // normalised height where the glow starts
uniform float glowRange;     // height over which it ramps to full strength
uniform float glowSpeed;     // pulse angular frequency (radians per second)
uniform float glowMin;       // pulse minimum (fraction of full glow)
uniform float glowStrength;

const float TWO_PI = 6.2831853;

void main()
{
    float len = length(IN.worldNormal);
    vec3 n = len > 1e-6 ? IN.worldNormal / len : vec3(0.0, 1.0, 0.0);
    float h = IN.height;

    // Colour bands by height.
    vec3 colour;
    if (h <= waterLevel)
    {
        // lake: deeper (lower terrain below the surface) is darker
        colour = mix(vec3(0.02, 0.08, 0.22), vec3(0.05, 0.3, 0.45), smoothstep(waterLevel - 0.25, waterLevel, h));
    }
    else
    {
        float above = h - waterLevel;
        colour = mix(vec3(0.72, 0.66, 0.42), vec3(0.18, 0.45, 0.12), smoothstep(0.0, 0.04, above));
        colour = mix(colour, vec3(0.38, 0.32, 0.26), smoothstep(0.18, 0.3, above));
        colour = mix(colour, vec3(0.2, 0.18, 0.2), smoothstep(0.3, 0.45, above)); // dark peaks, so the glow reads
    }

    vec3 lightDir = normalize(vec3(-0.5, 0.8, 0.35)); // constant, non-zero
    float diffuse = max(dot(n, lightDir), 0.0);
    vec3 lit = colour * (0.18 + 0.9 * diffuse);

    // Glow above the threshold, pulsing between glowMin and 1.
    // wrapped to [0, 2pi) before sin/cos (W0717): a phase that grows with time loses f32
    // precision after hours; fract(x / TWO_PI) * TWO_PI is mod(x, TWO_PI)
    float pulse = mix(glowMin, 1.0, 0.5 + 0.5 * sin(fract(time * glowSpeed / TWO_PI) * TWO_PI));
    float glowAmount = smoothstep(glowThreshold, glowThreshold + max(glowRange, 1e-3), h);
    vec3 glowColour = vec3(0.15, 1.0, 0.45);
    lit += glowColour * glowAmount * pulse * glowStrength;

    FragColor = vec4(lit, 1.0);
}
