#version 330 core
// Shifts by amounts within the width; arithmetic right shift of negatives.
in vec2 uv;
out vec4 color;

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    int s = p.y % 31;
    int l = (p.x + 1) << s;
    int r = (-p.x - 1) >> (p.y % 8);
    uint u = uint(p.x + 1) << uint(s);
    color = vec4(float((l >> s) == p.x + 1), float(r + 64) / 64.0, float(u >> 28) / 15.0, 1.0);
}
