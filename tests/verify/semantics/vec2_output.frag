#version 330 core
// A vec2 output: GL leaves blue and alpha of the target undefined, so only red and green
// are compared.
in vec2 uv;
out vec2 color;

void main()
{
    color = vec2(uv.x * uv.y, fract(uv.x * 4.0));
}
