#version 330 core
// Positions are clip-space already; the normal attribute carries a colour.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
out vec3 vColor;
void main() {
    vColor = normal;
    gl_Position = vec4(position, 1.0);
}
