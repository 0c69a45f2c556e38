#version 330 core
// The same instances, drawn without a geometry stage.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
out vec3 color;
void main() {
    color = normal;
    gl_Position = vec4(position + vec3(0.5 * float(gl_InstanceID), 0.0, 0.0), 1.0);
}
