#version 410 core
in vec2 uv;
out vec4 color;
void main() {
    color = vec4(fract(uv * 3.0), 0.5, 1.0);
}
