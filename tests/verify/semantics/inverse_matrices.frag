#version 330 core
// inverse of 2×2 and 4×4 matrices (naga's WGSL writer has none: effectc writes its own),
// against the driver's: the products with the originals, and single elements.
in vec2 uv;
out vec4 color;

void main()
{
    mat2 a = mat2(2.0 + uv.x, 0.5, uv.y, 1.5);
    mat4 b = mat4(1.0 + uv.x, 0.2, 0.1, 0.0,
                  0.3, 2.0, uv.y, 0.1,
                  0.0, 0.4, 1.5, 0.2,
                  0.1, 0.0, 0.3, 1.0 + uv.y);
    mat2 ia = inverse(a);
    mat4 ib = inverse(b);
    mat4 p = b * ib;
    color = vec4(ia[0][1] + 0.5, ib[2][1] + 0.5, p[1][1] * 0.5 + p[2][1] + p[3][0], (a * ia)[1][1] * 0.5 + ib[3][3] * 0.25);
}
