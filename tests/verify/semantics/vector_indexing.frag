#version 330 core
// A vector indexed with a dynamic int, read and written.
in vec2 uv;
out vec4 color;

void main()
{
    vec4 v = vec4(uv, 0.5, 1.0);
    int i = int(gl_FragCoord.x) % 4;
    v[i] = 1.0 - v[i];
    color = vec4(v[(i + 1) % 4], v[i], v.zw);
}
