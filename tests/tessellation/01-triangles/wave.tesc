#version 410 core
// Different levels on every edge and inside, written by one invocation.
layout(vertices = 3) out;
in vec3 controlPoint[];
out vec3 evaluationPoint[];
patch out vec3 tint;
void main() {
    evaluationPoint[gl_InvocationID] = controlPoint[gl_InvocationID] * 1.6;
    if (gl_InvocationID == 0) {
        gl_TessLevelOuter[0] = 3.0;
        gl_TessLevelOuter[1] = 5.0;
        gl_TessLevelOuter[2] = 2.0;
        gl_TessLevelInner[0] = 6.0;
        tint = vec3(0.6, 0.8, 1.0);
    }
}
