#version 150
// Built-in implementation constants naga does not declare (array sizes and expressions),
// and `invariant` on a user varying (naga takes it only on gl_Position).
in vec4 position;
invariant out vec4 tint;
out float ramp[min(gl_MaxVertexOutputComponents, 4)];
void main() {
    gl_Position = position;
    for (int i = 0; i < ramp.length(); i++) {
        ramp[i] = float(i) / float(min(gl_MaxDrawBuffers, 4));
    }
    tint = vec4(position.xy * 0.5 + 0.5, float(gl_MaxClipDistances) / 16.0, 1.0);
}
