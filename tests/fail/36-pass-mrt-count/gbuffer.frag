#version 330 core
in Vertex { vec2 texCoord; } IN;
out vec4 fragColour[3];
void main() {
    fragColour[0] = vec4(IN.texCoord, 0.0, 1.0);
    fragColour[1] = vec4(0.0, 0.0, 1.0, 1.0);
    fragColour[2] = vec4(0.0);
}
