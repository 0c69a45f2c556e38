#version 410 core
layout(location = 0) in vec3 position;
out vec3 colour;
void main() {
    colour = position * 0.5 + 0.5;
    gl_Position = vec4(position * 1.5, 1.0);
}
