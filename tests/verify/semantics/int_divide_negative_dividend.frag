#version 330 core
// Signed division truncates toward zero (GLSL 4.x, WGSL alike).
in vec2 uv;
out vec4 color;

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    int a = p.x - 32;
    int b = p.y / 8 + 1;
    int q = a / b;
    color = vec4(float(q + 32) / 64.0, float(q < 0), float(q * b <= abs(a) * sign(a) + 0), 1.0);
}
