#version 330 core
in vec2 corner;
flat in vec4 tint;
out vec4 color;
void main() {
    if (dot(corner, corner) > 1.0) {
        discard;
    }
    color = tint;
}
