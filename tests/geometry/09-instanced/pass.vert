#version 330 core
// Each instance one step to the right.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
out vec3 vColor;
void main() {
    vColor = normal;
    gl_Position = vec4(position + vec3(0.5 * float(gl_InstanceID), 0.0, 0.0), 1.0);
}
