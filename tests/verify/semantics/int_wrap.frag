#version 330 core
// Signed addition past the largest int wraps (two's complement).
in vec2 uv;
out vec4 color;

void main()
{
    int x = 2147483600 + int(gl_FragCoord.x);
    color = vec4(float(x < 0), float((x >> 24) & 255) / 255.0, float(x & 63) / 63.0, 1.0);
}
