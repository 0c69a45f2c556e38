#version 330 core
// Seed 003's single-direction bloom blur, unguarded: at bloomRange = 1 the curve divides
// by (ranger - 1) = 0, and 0 * inf is NaN in every pixel.
uniform sampler2D sceneTex;
uniform int bloomRange;
uniform float bloomIntensity;
in Vertex { vec2 texCoord; } IN;
out vec4 fragColor;
void main(void)
{
    fragColor = vec4(0, 0, 0, 1);
    vec2 delta = dFdx(IN.texCoord);
    float z = 0;
    int ranger = bloomRange;
    float startCurve = 8.0f;
    for (int i = 0; i < ranger; i++)
    {
        vec2 offset = delta * (z - (ranger - 1) / 2);
        vec4 tmp = texture(sceneTex, IN.texCoord.xy + offset);
        float curve = 1.0 / (pow(2.0, abs(-startCurve + (startCurve * 2) / (ranger - 1) * z)));
        fragColor += tmp * curve * bloomIntensity;
        z += 1.0;
    }
}
