#version 330 core
// Deferred renderer, G-buffer pass 4 (seed 001): unlit sky. A vertical gradient from
// the horizon colour to the zenith colour; normal alpha = 0 keeps it out of lighting.

uniform vec3 cameraPos;
uniform vec3 skyHorizon;
uniform vec3 skyZenith;

in Vertex {
    vec3 worldPos;
} IN;

out vec4 fragColour[4];

vec3 skyColour(vec3 dir)
{
    float up = clamp(dir.y, -1.0, 1.0);
    vec3 colour = mix(skyHorizon, skyZenith, smoothstep(0.0, 0.7, up));
    return mix(colour, skyHorizon * 0.35, smoothstep(0.0, -0.3, up));
}

void main(void)
{
    vec3 d = IN.worldPos - cameraPos;
    vec3 dir = d * inversesqrt(max(dot(d, d), 1e-12));
    fragColour[0] = vec4(skyColour(dir), 1.0);
    fragColour[1] = vec4(0.5, 0.5, 0.5, 0.0);   // alpha 0: unlit
    fragColour[2] = vec4(0.0, 0.0, 0.0, 1.0);
    fragColour[3] = vec4(IN.worldPos, 1.0);
}
