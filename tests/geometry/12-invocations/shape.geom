#version 400 core
// Three invocations per triangle: each emits a copy moved right by half a unit per
// invocation, in its own colour.
layout(triangles, invocations = 3) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 vColor[];
out vec3 color;
const vec3 colors[3] = vec3[3](vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0));
void main() {
    for (int i = 0; i < 3; i++) {
        gl_Position = gl_in[i].gl_Position + vec4(0.5 * float(gl_InvocationID), 0.0, 0.0, 0.0);
        color = colors[gl_InvocationID];
        EmitVertex();
    }
    EndPrimitive();
}
