#version 150
// A full interface (31 whole vec4 locations, lavapipe's most) beside an output the fragment
// stage never reads: packing counts only what the fragment stage receives, after the unread
// output is left out, so the program still fits.
in vec4 position;
flat out ivec4 f[31];
out float unread;
void main() {
    gl_Position = position;
    for (int i = 0; i < 31; i++)
        f[i] = ivec4(i * 4, i * 4 + 1, i * 4 + 2, i * 4 + 3);
    unread = position.x;
}
