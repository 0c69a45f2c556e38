#version 330 core
// mat2x3 * vec2 gives a vec3; mat3x2 * mat2x3 gives a 3×3 (columns × rows).
in vec2 uv;
out vec4 color;

void main()
{
    mat2x3 a = mat2x3(1.0, 0.5, 0.25, uv.x, uv.y, 0.75);
    mat3x2 b = mat3x2(0.1, 0.2, 0.3, 0.4, 0.5, 0.6);
    vec3 v = a * vec2(0.5, 1.0);
    mat3 c = a * b;
    color = vec4(v / 2.0, c[2][1]);
}
