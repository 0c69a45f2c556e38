#version 330 core
// Ray march across a height map until a texel rises above the threshold, with no cap on
// the steps: the only exit is the texture test. With heightThreshold above the map's
// highest texel (the noise never reaches 1.0) the loop never breaks, and i++ overflows.

uniform sampler2D heightMap;
uniform float heightThreshold;
uniform float stepSize;

in vec2 uv;
out vec4 fragColor;

void main()
{
    int steps = 0;
    vec2 p = uv;
    for (int i = 0; ; i++)
    {
        if (texture(heightMap, p).r > heightThreshold)
        {
            break;
        }
        p += vec2(stepSize, 0.5 * stepSize);
        steps = i;
    }
    fragColor = vec4(vec3(float(steps) / 64.0), 1.0);
}
