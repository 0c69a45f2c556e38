#version 330 core
// transpose, determinant, inverse, matrixCompMult, outerProduct.
in vec2 uv;
out vec4 color;

void main()
{
    mat3 m = mat3(2.0, uv.x, 0.0, 0.5, 1.0 + uv.y, 0.25, 0.0, 0.3, 1.5);
    mat3 t = transpose(m);
    mat3 i = inverse(m);
    mat3 p = matrixCompMult(m, t);
    mat2 o = outerProduct(vec2(uv.x, 1.0), vec2(0.5, uv.y));
    color = vec4(t[0][1], determinant(m) / 6.0, (m * i)[1][1] * 0.5, (p[2][1] + o[1][0]) * 0.5);
}
