#version 330 core
// exp, log, exp2, log2, pow with positive bases.
in vec2 uv;
out vec4 color;

void main()
{
    float x = uv.x * 2.0 + 0.05;
    color = vec4(exp(-x), log(x + 1.0) / 1.2, log2(x * 4.0) / 4.0, pow(x, uv.y * 3.0) / 9.0);
}
