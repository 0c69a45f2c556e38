#version 330 core
// A band of two triangles along the first edge (one strip of four vertices), then a small
// triangle at the third corner (a strip of three): two EndPrimitive calls, 7 of 10 slots.
layout(triangles) in;
layout(triangle_strip, max_vertices = 10) out;
in vec3 vColor[];
out vec3 color;
void corner(vec4 p, vec3 c) {
    gl_Position = p;
    color = c;
    EmitVertex();
}
void main() {
    vec4 up = vec4(0.0, 0.5, 0.0, 0.0);
    corner(gl_in[0].gl_Position, vec3(1.0, 0.0, 0.0));
    corner(gl_in[1].gl_Position, vec3(1.0, 0.0, 0.0));
    corner(gl_in[0].gl_Position + up, vec3(1.0, 0.0, 0.0));
    corner(gl_in[1].gl_Position + up, vec3(1.0, 0.0, 0.0));
    EndPrimitive();
    corner(gl_in[2].gl_Position, vec3(0.0, 1.0, 0.0));
    corner(gl_in[2].gl_Position + vec4(-0.25, -0.25, 0.0, 0.0), vec3(0.0, 1.0, 0.0));
    corner(gl_in[2].gl_Position + vec4(0.25, -0.25, 0.0, 0.0), vec3(0.0, 1.0, 0.0));
    EndPrimitive();
}
