#version 410 core
// A quad patch: four levels on the edges, two inside.
layout(vertices = 4) out;
in vec2 corner[];
out vec2 point[];
void main() {
    point[gl_InvocationID] = corner[gl_InvocationID] * 1.7;
    gl_TessLevelOuter[0] = 2.0;
    gl_TessLevelOuter[1] = 3.0;
    gl_TessLevelOuter[2] = 4.0;
    gl_TessLevelOuter[3] = 5.0;
    gl_TessLevelInner[0] = 4.0;
    gl_TessLevelInner[1] = 3.0;
}
