#version 150
in vec4 position;
out vec3 tint;
void main() {
    gl_Position = position;
    tint = position.xyz * 0.5 + 0.5;
}
