#version 330 core
// float → int conversion truncates toward zero, also for negatives.
in vec2 uv;
out vec4 color;

void main()
{
    vec2 f = uv * 10.0 - 5.0;
    ivec2 i = ivec2(f);
    uint u = uint(max(f.x, 0.0));
    color = vec4(float(i.x + 5) / 10.0, float(i.y + 5) / 10.0, float(u) / 5.0, 1.0);
}
