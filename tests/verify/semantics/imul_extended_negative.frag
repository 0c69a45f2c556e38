#version 400 core
// imulExtended of a negative and a positive operand: the high half is negative
// (-0x10000000 * 0x30 = -0x300000000: high -3, low 0).
in vec2 uv;
out vec4 color;

void main()
{
    int x = int(gl_FragCoord.x) % 8;
    int hi, lo;
    imulExtended(-x * 0x10000000, 0x30, hi, lo);
    vec2 f;
    ivec2 e;
    f = frexp(vec2(uv.x * 8.0 + 0.5, -uv.y * 3.0 - 0.25), e);
    color = vec4(float(hi + 64) / 128.0, float(lo & 255) / 255.0, f.x * 0.5 + abs(f.y) * 0.5, float(e.x + e.y + 4) / 16.0);
}
