#version 330 core
// a && f(): f runs only when a is true.
in vec2 uv;
out vec4 color;

float counter = 0.0;
bool bump(bool r) { counter += 1.0; return r; }

void main()
{
    bool a = uv.x > 0.5;
    bool c = a && bump(uv.y > 0.5);
    color = vec4(float(c), counter, float(a), 1.0);
}
