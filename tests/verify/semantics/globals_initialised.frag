#version 330 core
// A global initialised from an expression, read in a function.
in vec2 uv;
out vec4 color;

float scale = 0.5;
vec2 offset = vec2(0.25, 0.125);

vec2 shift(vec2 p) { return p * scale + offset; }

void main()
{
    scale += uv.y * 0.25;
    color = vec4(shift(uv), scale, 1.0);
}
