#version 330 core
// Integer and float expressions of constants, folded at translation.
in vec2 uv;
out vec4 color;

const int A = -7;
const int B = 3;
const float C = 1.0 / 3.0;
const uint D = 0xFFFFFFF0u;

void main()
{
    color = vec4(float(A / B + 5) / 8.0, float(A * B + 30) / 40.0, C * 2.0, float(D >> 28) / 15.0);
}
