#version 330 core
// Deferred renderer, G-buffer pass 1 (seed 001): terrain fragment stage.
// Writes the four G-buffer targets like the seed's terrain shader:
//   [0] diffuse, [1] normal * 0.5 + 0.5 with the "is lit" flag in alpha (1 = lit),
//   [2] glow: the seed's height-based green glow near the water, which the combine pass
//       adds without lighting, so the shore looks lit by the lake even where no light is,
//   [3] world position (depth targets cannot be sampled).

uniform sampler2D groundTex;
uniform float time;
uniform float waterLevel;      // rest height of the lake surface
uniform float levelAmplitude;  // the lake rises and falls by this much
uniform float levelSpeed;      // radians per second of the rise and fall
uniform float glowAbove;       // the glow reaches this far above the water surface
uniform float glowRange;       // height over which the glow fades out
uniform float glowStrength;    // brightness of the glow at and below the water line

in Vertex {
    vec2 texCoord;
    vec3 normal;
    vec3 worldPos;
} IN;

out vec4 fragColour[4];

// normalize() that cannot divide by zero: a mesh with zero normals (degenerate faces;
// `effectc stress`'s geometry cases) gives N = 0 here, not NaN.
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

void main(void)
{
    vec3 N = safeNormalize(IN.normal);
    float grain = texture(groundTex, IN.worldPos.xz * 0.35).r;

    // Sand at the shore, grass on the slopes, rock on steep parts.
    vec3 sand = vec3(0.78, 0.70, 0.48);
    vec3 grass = vec3(0.30, 0.52, 0.22);
    vec3 rock = vec3(0.45, 0.42, 0.40);
    float waterY = waterLevel + levelAmplitude * sin(wrapPhase(time * levelSpeed));
    vec3 colour = mix(sand, grass, smoothstep(waterY + 0.15, waterY + 0.45, IN.worldPos.y));
    colour = mix(colour, rock, smoothstep(0.75, 0.55, N.y));
    colour *= 0.75 + 0.5 * grain;

    fragColour[0] = vec4(colour, 1.0);
    fragColour[1] = vec4(N * 0.5 + 0.5, 1.0);
    fragColour[1].a = 1.0;                 // lit

    vec3 GREEN = vec3(0.0, 1.0, 0.0);
    float maxGlowHeight = waterY + glowAbove;
    float glow = max((maxGlowHeight - IN.worldPos.y) / max(glowRange, 1e-3), 0.0);
    fragColour[2].rgb = fragColour[0].rgb * GREEN * min(glow, 1.0) * glowStrength;
    fragColour[2].a = 1.0;

    fragColour[3] = vec4(IN.worldPos, 1.0);
}
