#version 330 core
// floor, ceil, fract, trunc, roundEven of negative and positive values.
in vec2 uv;
out vec4 color;

void main()
{
    float x = uv.x * 8.0 - 4.0 + 0.25;
    color = vec4((floor(x) + 4.0) / 8.0, (ceil(x) + 4.0) / 8.0, fract(x), (trunc(x) + roundEven(x * 2.0 + 0.5) * 0.5 + 8.0) / 16.0);
}
