#version 410 core
// The geometry stage sees each generated triangle: it marks its edges.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 tessCoord[];
out vec3 barycentric;
out vec3 shade;
void main() {
    for (int i = 0; i < 3; i++) {
        gl_Position = gl_in[i].gl_Position;
        barycentric = vec3(i == 0, i == 1, i == 2);
        shade = tessCoord[i];
        EmitVertex();
    }
    EndPrimitive();
}
