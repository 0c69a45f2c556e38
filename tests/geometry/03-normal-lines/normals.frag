#version 410 core
in float along;
layout(location = 0) out vec4 color;
void main() {
    color = mix(vec4(1.0, 1.0, 0.0, 1.0), vec4(1.0, 0.0, 0.0, 1.0), along);
}
