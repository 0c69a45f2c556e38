#version 110
// A video frame drawn from a rectangle texture; the same fragment stage serves 2D
// textures when the host leaves RECT undefined (a video player's shader permutation).
varying vec2 coord;

void main()
{
    coord = gl_MultiTexCoord0.xy * 256.0;
    gl_Position = ftransform();
}
