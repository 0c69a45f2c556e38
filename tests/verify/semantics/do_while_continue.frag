#version 330 core
// continue in do { } while (c) evaluates the condition.
in vec2 uv;
out vec4 color;

void main()
{
    int n = int(gl_FragCoord.x) % 9;
    int i = 0;
    int odd = 0;
    do {
        i++;
        if (i % 2 == 0) continue;
        odd++;
    } while (i < n);
    color = vec4(float(i) / 9.0, float(odd) / 5.0, 0.0, 1.0);
}
