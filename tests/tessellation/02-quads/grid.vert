#version 410 core
layout(location = 0) in vec3 position;
out vec2 corner;
void main() {
    corner = position.xy;
    gl_Position = vec4(position, 1.0);
}
