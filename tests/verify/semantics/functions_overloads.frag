#version 330 core
// Overloaded user functions chosen by argument type.
in vec2 uv;
out vec4 color;

float f(float x) { return x * 0.5; }
float f(vec2 v) { return v.x * v.y; }
int f(int i) { return i / 2; }

void main()
{
    color = vec4(f(uv.x), f(uv), float(f(int(gl_FragCoord.x))) / 32.0, 1.0);
}
