#version 400 core
// uaddCarry, usubBorrow, umulExtended, imulExtended (non-negative operands; see
// imul_extended_negative for the sign).
in vec2 uv;
out vec4 color;

void main()
{
    uvec2 p = uvec2(gl_FragCoord.xy);
    uint carry, borrow, hi, lo;
    uint s = uaddCarry(0xFFFFFFF0u + p.x, p.y, carry);
    uint d = usubBorrow(p.x, p.y, borrow);
    umulExtended(p.x * 0x10000000u, 0x30u + p.y, hi, lo);
    int ihi, ilo;
    imulExtended(int(p.x) * 0x1000000, 0x30 + int(p.y), ihi, ilo);
    color = vec4(float(carry), float(borrow), float(hi & 63u) / 63.0, float(ihi & 63) / 63.0 + float(s & 0u) + float(d & 0u) + float(lo & 0u));
}
