#version 330 core
// Pass-through: the instances arrive moved by the vertex stage.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 vColor[];
out vec3 color;
void main() {
    for (int i = 0; i < 3; i++) {
        gl_Position = gl_in[i].gl_Position;
        color = vColor[i];
        EmitVertex();
    }
    EndPrimitive();
}
