#version 330 core
out vec4 fragColor;
void main() {
    fragColor = vec4(0.2, 0.4, 0.9, 1.0);
}
