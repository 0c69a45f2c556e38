#version 330 core
// Bitwise and, or, xor, not on ints and uints.
in vec2 uv;
out vec4 color;

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    int a = p.x & p.y;
    int o = p.x | p.y;
    int x = p.x ^ p.y;
    uint n = ~uint(p.x);
    color = vec4(float(a) / 63.0, float(o) / 63.0, float(x) / 63.0, float(n >> 26) / 63.0);
}
