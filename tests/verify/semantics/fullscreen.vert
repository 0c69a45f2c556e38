#version 330 core
// A full-screen triangle made from gl_VertexID: no vertex buffer. `uv` runs 0..1 across
// the frame (0 at the bottom, as GL's window coordinates).
out vec2 uv;

void main()
{
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    uv = p;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
