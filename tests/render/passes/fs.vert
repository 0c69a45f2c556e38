#version 330 core
// Tutorial-style full-screen vertex stage: the input and the block member share the name
// `texCoord` (naga would read the member for the input; effectc renames the member).
in vec3 position;
in vec2 texCoord;
out Vertex { vec2 texCoord; } OUT;
void main() {
    OUT.texCoord = texCoord;
    gl_Position = vec4(position.xy, 0.0, 1.0);
}
