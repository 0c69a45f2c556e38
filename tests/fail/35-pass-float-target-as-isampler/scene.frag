#version 330 core
in Vertex { vec2 texCoord; } IN;
out vec4 fragColor;
void main() {
    fragColor = vec4(IN.texCoord, 0.5, 1.0);
}
