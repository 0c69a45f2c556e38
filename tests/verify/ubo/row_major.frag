#version 330
// Row-major block matrices (`layout(row_major)` on a member, on a block, and a member's
// `column_major` overriding its block's): GL stores them transposed; a value set by name is
// the matrix as GLSL reads it.
layout(std140) uniform Rows {
    layout(row_major) mat3 turn;
    mat3 plain;
};
layout(std140, row_major) uniform Mixed {
    mat4 whole;
    layout(column_major) mat4 kept;
} mixed;
out vec4 color;
void main() {
    vec3 a = turn * vec3(1.0, 0.0, 0.0) + plain[1];
    vec4 b = mixed.whole[0] + mixed.kept * vec4(0.0, 0.0, 1.0, 0.0);
    color = vec4(a.x, a.y + b.x, b.y, 1.0) * 0.5;
}
