#version 330 core
// A local array written and read at dynamic indices.
in vec2 uv;
out vec4 color;

void main()
{
    float a[8];
    for (int i = 0; i < 8; i++) a[i] = float(i) / 8.0;
    int k = int(gl_FragCoord.x) % 8;
    a[k] = 1.0 - a[k];
    a[(k + 3) % 8] += 0.0625;
    color = vec4(a[k], a[(k + 3) % 8], a[int(gl_FragCoord.y) % 8], 1.0);
}
