#version 330 core
// Pass-through that numbers its primitives for the fragment stage.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 vColor[];
void main() {
    for (int i = 0; i < 3; i++) {
        gl_Position = gl_in[i].gl_Position;
        gl_PrimitiveID = gl_PrimitiveIDIn;
        EmitVertex();
    }
    EndPrimitive();
}
