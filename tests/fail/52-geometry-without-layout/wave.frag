#version 330 core
in vec3 faceColor;
out vec4 color;
void main() {
    color = vec4(faceColor, 1.0);
}
