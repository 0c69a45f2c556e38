#version 400 core
// modf and frexp/ldexp.
in vec2 uv;
out vec4 color;

void main()
{
    float whole;
    float part = modf(uv.x * 5.0 - 2.5, whole);
    int e;
    float m = frexp(uv.y * 40.0 + 1.0, e);
    color = vec4(part * 0.5 + 0.5, (whole + 3.0) / 6.0, m, float(e) / 8.0 + ldexp(0.0, 2));
}
