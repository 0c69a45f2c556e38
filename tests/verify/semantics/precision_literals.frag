#version 330 core
// Float literals: exponents, suffixes, tiny and huge values.
in vec2 uv;
out vec4 color;

void main()
{
    float a = 1.5e-3 * 400.0;
    float b = 2.5E2 / 500.0;
    float c = 3.0f * 0.1;
    float d = 1e30 * 1e-30 * uv.x;
    color = vec4(a, b, c, d);
}
