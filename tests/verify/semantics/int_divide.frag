#version 330 core
// Integer division and remainder of non-negative operands (truncation).
in vec2 uv;
out vec4 color;

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    int a = p.x * 3 + 1;
    int b = p.y % 7 + 1;
    color = vec4(float(a / b) / 192.0, float(a % b) / 7.0, float((a / b) * b + a % b == a), 1.0);
}
