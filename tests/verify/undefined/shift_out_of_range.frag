#version 330 core
// Undefined in GLSL: a shift by 32 or more.
in vec2 uv;
out vec4 color;

void main()
{
    int s = int(gl_FragCoord.y) % 40;
    int v = 1 << s;
    color = vec4(float(v & 255) / 255.0, float(v < 0), uv.x, 1.0);
}
