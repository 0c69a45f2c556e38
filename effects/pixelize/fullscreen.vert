#version 330 core
// Fullscreen pass vertex stage (pixelize, seed 003): the fullscreen triangle's clip-space
// position passed through, its texture coordinate handed to the fragment stage.

in vec2 position; // clip space, -1..3 (one triangle covers the screen)
in vec2 texCoord; // 0..2 (0..1 across the visible part)

out Vertex
{
    vec2 texCoord;
} OUT;

void main(void)
{
    OUT.texCoord = texCoord;
    gl_Position = vec4(position.xy, 0.0, 1.0);
}
