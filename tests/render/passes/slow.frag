#version 330 core
// Runs for minutes: a pass drawing this must be skipped, or the render times out.
// Nested loops that keep every pixel busy for a long time: stands in for a shader that
// never finishes (lavapipe caps single loops, so a plain `while (true)` ends by itself).
in Vertex { vec2 texCoord; } IN;
out vec4 fragColor;
uniform float seed;
void main()
{
    float x = seed + IN.texCoord.x;
    for (int i = 0; i < 100000; i++)
    {
        for (int j = 0; j < 100000; j++)
        {
            x = fract(sin(x * 1.618 + float(j)) * 43758.5);
        }
    }
    fragColor = vec4(x);
}
