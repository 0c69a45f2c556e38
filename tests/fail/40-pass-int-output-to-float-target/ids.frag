#version 330 core
in Vertex { vec2 texCoord; } IN;
out ivec4 objectId;
void main() {
    objectId = ivec4(IN.texCoord * 255.0, 0, 1);
}
