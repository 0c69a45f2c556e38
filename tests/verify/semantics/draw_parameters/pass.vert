#version 460
// The draw parameters (GL 4.6) in a vertex stage: WGSL has no built-ins for them, so they
// come from the shared uniform block, zero for effectc's draw as for GL's glDrawArrays.
in vec4 position;
out vec4 params;
void main() {
    gl_Position = position;
    vec2 p = position.xy * 0.5 + 0.5;
    params = vec4(p, 0.25 + float(gl_BaseVertex) + float(gl_DrawID), 0.5 + float(gl_BaseInstance) + float(gl_InstanceID));
}
