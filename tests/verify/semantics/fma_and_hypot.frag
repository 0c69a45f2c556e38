#version 400 core
// fma, and sums that cancel (a + b - a).
in vec2 uv;
out vec4 color;

void main()
{
    float a = 1e4 + uv.x;
    float b = fma(uv.x, uv.y, 0.25);
    color = vec4(b, (a - 1e4), fract(a * 0.001), 1.0);
}
