#version 330 core
// dFdx, dFdy (their sign follows GL's upward y), fwidth.
in vec2 uv;
out vec4 color;

void main()
{
    float f = uv.x * uv.x * 16.0 + uv.y * 8.0;
    color = vec4(dFdx(f) * 8.0 + 0.5, dFdy(f) * 8.0 + 0.5, fwidth(f) * 4.0, dFdy(uv.y) * 32.0 + 0.5);
}
