#version 330 core
// m * v treats v as a column, v * m as a row.
in vec2 uv;
out vec4 color;

void main()
{
    mat2 m = mat2(1.0, 2.0, 3.0, 4.0);
    vec2 v = uv;
    color = vec4((m * v) / 6.0, (v * m) / 8.0);
}
