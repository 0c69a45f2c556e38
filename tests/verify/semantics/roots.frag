#version 330 core
// sqrt and inversesqrt.
in vec2 uv;
out vec4 color;

void main()
{
    float x = uv.x + 0.01;
    color = vec4(sqrt(x), inversesqrt(x) / 10.0, sqrt(uv.y * 4.0) / 2.0, 1.0);
}
