#version 450 core
// Varyings of aggregate type in a program that goes through glslang's SPIR-V (the fragment
// stage pastes tokens with `##`, which naga's GLSL front does not take): an array, a
// matrix, a flat integer array and a block member array each become one varying per
// element or column, at the locations GL gives them; the fragment stage indexes the array
// at run time.
in vec4 position;
out vec4 offsets[3];
out mat2 spin;
flat out ivec2 cells[2];
out Surface {
    vec2 uv[2];
    float weight;
} surface;
void main() {
    gl_Position = position;
    vec2 p = position.xy * 0.5 + 0.5;
    for (int i = 0; i < 3; i++) {
        offsets[i] = vec4(p * float(i + 1) * 0.25, float(i) * 0.3, 1.0);
    }
    spin = mat2(p.x, p.y, 1.0 - p.y, 0.5);
    cells[0] = ivec2(p * 4.0);
    cells[1] = ivec2(3) - ivec2(p * 4.0);
    surface.uv[0] = p.yx;
    surface.uv[1] = p * p;
    surface.weight = p.x * p.y;
}
