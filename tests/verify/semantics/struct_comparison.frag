#version 330 core
// == and != on structs compare every member.
in vec2 uv;
out vec4 color;

struct S { vec2 a; int b; };

void main()
{
    S x = S(floor(uv * 4.0), int(gl_FragCoord.x) / 32);
    S y = S(vec2(1.0, 2.0), 0);
    color = vec4(float(x == y), float(x != y), float(x.a == y.a), 1.0);
}
