#version 330 core
// A quad (a strip of four) around every input point, in the point's colour.
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
in vec3 vColor[];
out vec3 color;
void main() {
    vec4 p = gl_in[0].gl_Position;
    color = vColor[0];
    gl_Position = p + vec4(-0.125, -0.125, 0.0, 0.0); EmitVertex();
    gl_Position = p + vec4(0.125, -0.125, 0.0, 0.0); EmitVertex();
    gl_Position = p + vec4(-0.125, 0.125, 0.0, 0.0); EmitVertex();
    gl_Position = p + vec4(0.125, 0.125, 0.0, 0.0); EmitVertex();
    EndPrimitive();
}
