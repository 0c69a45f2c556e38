#version 330 core
in vec2 uv;
out vec4 color;

uniform sampler2D image;
uniform int taps;
uniform uint passes;

void main()
{
    vec4 sum = vec4(0.0);
    for (int i = 0; i < taps; i++) {
        sum += texture(image, uv + vec2(float(i) * 0.001, 0.0));
    }
    for (int i = taps; i > 0; i--) {
        sum += texture(image, uv - vec2(float(i) * 0.001, 0.0));
    }
    for (uint k = 0u; k < passes; k++) {
        sum *= 0.5;
    }
    color = sum;
}
