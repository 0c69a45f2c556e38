#version 330 core
// == on arrays compares every element.
in vec2 uv;
out vec4 color;

void main()
{
    float a[2] = float[2](floor(uv.x * 3.0), floor(uv.y * 3.0));
    float b[2] = float[2](1.0, 1.0);
    color = vec4(float(a == b), float(a[0] == b[0]), float(a != b), 1.0);
}
