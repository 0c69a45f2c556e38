#version 330 core
// The output primitive is declared, but not how many vertices one invocation may emit.
layout(triangles) in;
layout(triangle_strip) out;
in vec3 worldPos[];
out vec3 faceColor;
void main() {
    for (int i = 0; i < 3; i++) {
        faceColor = abs(worldPos[i]);
        gl_Position = gl_in[i].gl_Position;
        EmitVertex();
    }
    EndPrimitive();
}
