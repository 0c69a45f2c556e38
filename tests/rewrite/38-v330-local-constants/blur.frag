#version 330 core
in vec2 uv;
uniform sampler2D image;
uniform int mode;
out vec4 color;
void main()
{
    // Local constants size arrays and label cases; naga resolves neither, so the
    // rewrite writes their values.
    const int TAPS = 3;
    const int SHOW_WEIGHTS = 2;
    float weights[TAPS + 1];
    for (int i = 0; i <= TAPS; i++) {
        weights[i] = 1.0 / float(TAPS + 1);
    }
    vec4 sum = vec4(0.0);
    for (int i = 0; i <= TAPS; i++) {
        sum += texture(image, uv + vec2(float(i) * 0.01, 0.0)) * weights[i];
    }
    switch (mode) {
    case SHOW_WEIGHTS:
        color = vec4(weights[0]);
        break;
    default:
        color = sum;
        break;
    }
}
