#version 410 core
// The classic normal visualisation: one short line per vertex, three strips per triangle.
layout(triangles) in;
layout(line_strip, max_vertices = 6) out;
in VertexData {
    vec3 normal;
} vertexIn[];
uniform mat4 projection;
uniform float lineLength;
out float along;
void line(int i) {
    along = 0.0;
    gl_Position = projection * gl_in[i].gl_Position;
    EmitVertex();
    along = 1.0;
    gl_Position = projection * (gl_in[i].gl_Position + vec4(normalize(vertexIn[i].normal) * lineLength, 0.0));
    EmitVertex();
    EndPrimitive();
}
void main() {
    line(0);
    line(1);
    line(2);
}
