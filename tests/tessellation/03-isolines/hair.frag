#version 410 core
in float along;
out vec4 color;
void main() {
    color = vec4(along, 1.0 - along, 1.0, 1.0);
}
