#version 420 core
// Sun glow: the surface texture plus an in-shader box blur whose strength pulses between
// minBI and maxBI at bFrequency (seed 000). The seed's fragment stage declared
// `in vert_vars`, which does not link with the vertex stage's `out vert_out`: fixed here.

in vert_out
{
    vec2 outputTexCoords;
    vec3 swirlPosVector;
} frag_in;

out vec4 fragColor;

uniform sampler2D textureSamplerVar;
uniform float timeVarFrag; // Time in seconds
uniform float minBI;       // Minimum bloom intensity
uniform float maxBI;       // Maximum bloom intensity
uniform float bFrequency;  // Bloom pulse frequency (radians per second)

uniform int blurEffectRadius; // quality knob: (2r+1)^2 taps, 169 at the default 6

const float TWO_PI = 6.2831853;

void main()
{
    vec4 textureColour = texture(textureSamplerVar, frag_in.outputTexCoords);

    // wrapped to [0, 2pi) before sin/cos (W0717): a phase that grows with time loses f32
    // precision after hours; fract(x / TWO_PI) * TWO_PI is mod(x, TWO_PI)
    float currentBI = mix(minBI, maxBI, 0.5 + 0.5 * sin(fract(timeVarFrag * bFrequency / TWO_PI) * TWO_PI));

    vec3 bloomEffectColour = vec3(0.0);
    vec2 texelSize = 1.0 / vec2(textureSize(textureSamplerVar, 0));
    for (int x = -blurEffectRadius; x <= blurEffectRadius; x++)
    {
        for (int y = -blurEffectRadius; y <= blurEffectRadius; y++)
        {
            vec2 offsetVector = vec2(x, y);
            vec4 bloomEffectSample = texture(textureSamplerVar, frag_in.outputTexCoords + offsetVector * texelSize);
            bloomEffectColour += bloomEffectSample.rgb;
        }
    }

    bloomEffectColour /= float((blurEffectRadius * 2 + 1) * (blurEffectRadius * 2 + 1));
    bloomEffectColour *= currentBI;

    vec3 outputColour = textureColour.rgb + bloomEffectColour;
    fragColor = vec4(outputColour, 1.0);
}
