#version 330 core
// An array element passed as an inout argument is written back.
in vec2 uv;
out vec4 color;

void bump(inout float x) { x += 0.25; }

void main()
{
    float a[3] = float[3](0.0, uv.x * 0.5, uv.y * 0.5);
    int i = int(gl_FragCoord.x) % 3;
    bump(a[i]);
    color = vec4(a[0], a[1], a[2], 1.0);
}
