#version 420
// A textured mesh handed to a geometry stage through a named block and a loose varying.
uniform mat4 modelViewProjection;
layout(location = 0) in vec3 position;
layout(location = 1) in vec2 uv;
layout(location = 2) in vec3 normal;
out vec3 shadeNormal;
out Surface {
    vec2 uv;
} surface;
void main() {
    shadeNormal = normal;
    surface.uv = uv;
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
