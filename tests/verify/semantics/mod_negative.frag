#version 330 core
// GLSL mod(x, y) is x - y·floor(x/y): non-negative for positive y.
in vec2 uv;
out vec4 color;

void main()
{
    float x = uv.x * 10.0 - 5.0;
    float m = mod(x, 3.0);
    vec2 mv = mod(vec2(x, -x), vec2(2.5));
    color = vec4(m / 3.0, mv / 2.5, 1.0);
}
