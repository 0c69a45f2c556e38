#version 330 core
// Fullscreen triangle (seed 001 deferred renderer): passes the uv through for the
// combine pass.

layout(location = 0) in vec3 position;
layout(location = 1) in vec2 texCoord;

out Vertex {
    vec2 texCoord;
} OUT;

void main(void)
{
    OUT.texCoord = texCoord;
    gl_Position = vec4(position.xy, 0.0, 1.0);
}
