#version 330 core
// mat2(mat4) keeps the upper-left block; mat4(mat3) extends with the identity.
in vec2 uv;
out vec4 color;

void main()
{
    mat3 a = mat3(uv.x, 0.1, 0.2, 0.3, uv.y, 0.4, 0.5, 0.6, 0.7);
    mat4 b = mat4(a);
    mat2 c = mat2(b);
    color = vec4(b[3][3], b[0][3] + b[3][0], c[1][1], c[0][1] * 2.0);
}
