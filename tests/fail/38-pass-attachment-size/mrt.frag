#version 330 core
in Vertex { vec2 texCoord; } IN;
layout(location = 0) out vec4 colour;
layout(location = 1) out vec4 bright;
void main() {
    colour = vec4(IN.texCoord, 0.0, 1.0);
    bright = max(colour - 0.5, 0.0);
}
