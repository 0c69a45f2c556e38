#version 330 core
// out/inout arguments that are part of a variable: a vector component (constant and
// variable index), a swizzle, an array element. GLSL copies each in and back out.
in vec2 uv;
out vec4 color;

void bump(inout float x) { x += 0.25 + 0.25 * x; }
void halves(out vec2 y) { y = vec2(0.5, 0.125); }

void main()
{
    vec4 v = vec4(uv, 0.0, 0.0);
    int i = int(gl_FragCoord.x) % 2;
    bump(v.x);
    bump(v[i + 1]);
    halves(v.zw);
    float a[2] = float[2](0.0, uv.y);
    bump(a[i]);
    color = vec4(v.xyz, v.w + a[0] * 0.5 + a[1] * 0.25);
}
