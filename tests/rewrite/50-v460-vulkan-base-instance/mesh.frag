#version 460
layout(location = 0) in vec3 inColor;
layout(location = 0) out vec4 outFragColor;
void main() {
    outFragColor = vec4(inColor + vec3(0.5, 0.25, 0.0), 1.0);
}
