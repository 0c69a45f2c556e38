#version 330 core
// atan(y, x) in every quadrant (the origin left out).
in vec2 uv;
out vec4 color;

void main()
{
    vec2 d = uv * 2.0 - 1.0 + vec2(0.013, 0.007);
    float a = atan(d.y, d.x);
    color = vec4(a / 6.2831853 + 0.5, atan(d.y / 2.0) / 3.1415926 + 0.5, float(a < 0.0), 1.0);
}
