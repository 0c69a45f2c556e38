#version 410 core
// Control points straight from the mesh; the evaluation stage displaces the surface.
layout(location = 0) in vec3 position;
out vec3 controlPoint;
void main() {
    controlPoint = position;
    gl_Position = vec4(position, 1.0);
}
