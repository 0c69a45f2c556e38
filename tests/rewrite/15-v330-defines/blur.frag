#version 330 core
#define TAPS 5
#define WEIGHT(i) (1.0 / float(TAPS))
#ifndef HORIZONTAL
#define DIR vec2(0.0, 1.0)
#else
#define DIR vec2(1.0, 0.0)
#endif

in vec2 uv;

uniform sampler2D image;
uniform vec2 texel;

out vec4 fragColor;

void main()
{
    vec4 sum = vec4(0.0);
    for (int i = 0; i < TAPS; i++) {
        sum += texture(image, uv + DIR * texel * float(i - TAPS / 2)) * WEIGHT(i);
    }
#if TAPS > 3
    fragColor = sum;
#else
    fragColor = vec4(1.0, 0.0, 1.0, 1.0);
#endif
}
