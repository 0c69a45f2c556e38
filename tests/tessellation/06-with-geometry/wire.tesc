#version 410 core
// Levels of 2: every edge halved, the centre fanned to the six half-edges.
layout(vertices = 3) out;
in vec3 controlPoint[];
out vec3 point[];
void main() {
    point[gl_InvocationID] = controlPoint[gl_InvocationID];
    gl_TessLevelOuter[0] = 2.0;
    gl_TessLevelOuter[1] = 2.0;
    gl_TessLevelOuter[2] = 2.0;
    gl_TessLevelInner[0] = 2.0;
}
