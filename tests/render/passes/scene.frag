#version 330 core
// Two outputs: the uv gradient, and a spare one nobody reads (its attachment is dropped).
in Vertex { vec2 texCoord; } IN;
layout(location = 0) out vec4 colour;
layout(location = 1) out vec4 spare;
void main() {
    colour = vec4(IN.texCoord, 0.5, 1.0);
    spare = vec4(1.0, 0.0, 1.0, 1.0);
}
