#version 410 core
// Isolines: outer[0] lines of outer[1] segments each.
layout(vertices = 4) out;
void main() {
    gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
    gl_TessLevelOuter[0] = 6.0;
    gl_TessLevelOuter[1] = 8.0;
}
