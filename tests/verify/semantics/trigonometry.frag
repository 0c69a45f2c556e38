#version 330 core
// sin, cos, tan, asin, acos within their domains.
in vec2 uv;
out vec4 color;

void main()
{
    float a = uv.x * 6.0 - 3.0;
    color = vec4(sin(a) * 0.5 + 0.5, cos(a) * 0.5 + 0.5, clamp(tan(a * 0.4) * 0.2 + 0.5, 0.0, 1.0),
                 (asin(uv.y * 2.0 - 1.0) + acos(uv.x * 1.8 - 0.9)) / 5.0 + 0.2);
}
