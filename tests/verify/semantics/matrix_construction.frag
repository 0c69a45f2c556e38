#version 330 core
// Matrices are built column by column; m[c][r] picks column c, row r.
in vec2 uv;
out vec4 color;

void main()
{
    float s = uv.x;
    mat3 m = mat3(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, s);
    color = vec4(m[1][2] / 9.0, m[2][0] / 9.0, m[2][2], m[0].y / 9.0);
}
