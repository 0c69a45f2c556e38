#version 330 core
// while with a data-dependent trip count.
in vec2 uv;
out vec4 color;

void main()
{
    float x = uv.x * 100.0 + 1.0;
    int steps = 0;
    while (x > 1.0) {
        x *= 0.5;
        steps++;
    }
    color = vec4(float(steps) / 7.0, x, 0.0, 1.0);
}
