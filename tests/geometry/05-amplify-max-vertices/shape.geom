#version 330 core
// Three half-size copies of each triangle, each its own strip: the whole max_vertices.
layout(triangles) in;
layout(triangle_strip, max_vertices = 9) out;
in vec3 vColor[];
out vec3 color;
const vec2 offsets[3] = vec2[3](vec2(0.0, 0.0), vec2(0.75, 0.0), vec2(0.375, 0.75));
const vec3 colors[3] = vec3[3](vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0));
void main() {
    for (int copy = 0; copy < 3; copy++) {
        for (int i = 0; i < 3; i++) {
            gl_Position = vec4(gl_in[i].gl_Position.xy * 0.5 + offsets[copy], 0.0, 1.0);
            color = colors[copy];
            EmitVertex();
        }
        EndPrimitive();
    }
}
