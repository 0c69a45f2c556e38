#version 330 core
// Every triangle twice: in place to layer 0 (red), moved up to layer 1 (green).
layout(triangles) in;
layout(triangle_strip, max_vertices = 6) out;
in vec3 vColor[];
out vec3 color;
void main() {
    for (int layer = 0; layer < 2; layer++) {
        for (int i = 0; i < 3; i++) {
            gl_Layer = layer;
            gl_Position = gl_in[i].gl_Position + vec4(0.0, 0.75 * float(layer), 0.0, 0.0);
            color = layer == 0 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
            EmitVertex();
        }
        EndPrimitive();
    }
}
