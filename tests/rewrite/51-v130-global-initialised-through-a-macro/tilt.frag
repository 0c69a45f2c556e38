#version 130
in vec2 shade;
out vec4 colour;
void main() {
    colour = vec4(shade, 0.5, 1.0);
}
