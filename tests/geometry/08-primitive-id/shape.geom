#version 330 core
// Each triangle as it came, in the colour its primitive number picks.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 vColor[];
out vec3 color;
const vec3 palette[4] = vec3[4](vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0), vec3(0.6, 0.8, 0.0));
void main() {
    for (int i = 0; i < 3; i++) {
        gl_Position = gl_in[i].gl_Position;
        color = palette[gl_PrimitiveIDIn % 4];
        EmitVertex();
    }
    EndPrimitive();
}
