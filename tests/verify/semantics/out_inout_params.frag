#version 330 core
// out and inout parameters are copied back after the call.
in vec2 uv;
out vec4 color;

void split(float x, out float whole, out float part) { whole = floor(x); part = x - whole; }
void twice(inout vec2 v) { v *= 2.0; }

void main()
{
    float w, p;
    split(uv.x * 4.0, w, p);
    vec2 v = uv * 0.5;
    twice(v);
    color = vec4(w / 4.0, p, v);
}
