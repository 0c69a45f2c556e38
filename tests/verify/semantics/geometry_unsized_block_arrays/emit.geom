#version 150
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in Carried {
    float tint[];
    vec2 lift[];
} carried[];
in Bare {
    float shade[];
} bare[];
out vec4 color;
void main() {
    for (int i = 0; i < 3; i++) {
        gl_Position = gl_in[i].gl_Position;
        color = vec4(carried[i].tint[0], carried[i].tint[2] + carried[i].lift[1].x, bare[i].shade[1], 1.0);
        EmitVertex();
    }
}
