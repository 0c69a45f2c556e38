#version 330 core
// Fullscreen pass vertex stage (screen fade, seed 001): passes the fullscreen triangle's
// clip-space position through and hands its texture coordinate to the fragment stage.

layout(location = 0) in vec3 position; // clip space, -1..3 (one triangle covers the screen)
layout(location = 1) in vec2 texCoord; // 0..2 (0..1 across the visible part)

out Vertex
{
    vec2 texCoord;
} OUT;

void main(void)
{
    OUT.texCoord = texCoord;
    gl_Position = vec4(position.xy, 0.0, 1.0);
}
