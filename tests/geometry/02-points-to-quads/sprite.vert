#version 330 core
// One point per particle; the geometry stage grows each into a camera-facing quad.
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 color;
uniform mat4 view;
out vec4 pointColor;
void main() {
    pointColor = color;
    gl_Position = view * vec4(position, 1.0);
}
