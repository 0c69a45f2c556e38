#version 330 core
// The expected triangle, drawn without a geometry stage (the normal is the colour).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
out vec3 color;
void main() {
    color = normal;
    gl_Position = vec4(position, 1.0);
}
