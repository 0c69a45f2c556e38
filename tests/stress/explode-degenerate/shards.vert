#version 420
// Clip-space positions and texture coordinates for the geometry stage.
uniform mat4 mvp;
layout(location = 0) in vec3 position;
layout(location = 1) in vec2 uv;
out vert_vars { vec2 uv; } vert_out;
void main() {
    vert_out.uv = uv;
    gl_Position = mvp * vec4(position, 1.0);
}
