#version 410 core
in vec3 barycentric;
in vec3 shade;
out vec4 color;
void main() {
    float edge = min(min(barycentric.x, barycentric.y), barycentric.z);
    color = vec4(edge < 0.04 ? vec3(1.0) : shade, 1.0);
}
