#version 410 core
// Each invocation reads what the others wrote before the barrier.
layout(vertices = 3) out;
in vec3 controlPoint[];
out vec3 point[];
patch out vec3 centre;
void main() {
    point[gl_InvocationID] = controlPoint[gl_InvocationID];
    barrier();
    if (gl_InvocationID == 0) {
        centre = (point[0] + point[1] + point[2]) / 3.0;
        gl_TessLevelOuter[0] = 4.0;
        gl_TessLevelOuter[1] = 4.0;
        gl_TessLevelOuter[2] = 4.0;
        gl_TessLevelInner[0] = 4.0;
    }
}
