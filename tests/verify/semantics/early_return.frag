#version 330 core
// return from main and from inside loops of a function.
in vec2 uv;
out vec4 color;

float firstAbove(float t)
{
    for (int i = 0; i < 16; i++) {
        if (float(i) / 16.0 > t) return float(i) / 16.0;
    }
    return 1.0;
}

void main()
{
    color = vec4(firstAbove(uv.x), 0.0, 0.0, 1.0);
    if (uv.y > 0.5) return;
    color.g = 1.0;
}
