#version 330 core
// for with break and continue; nested loops.
in vec2 uv;
out vec4 color;

void main()
{
    int n = int(gl_FragCoord.x) % 12;
    int sum = 0;
    for (int i = 0; i < 20; i++) {
        if (i == n) break;
        if (i % 3 == 0) continue;
        for (int j = 0; j < 3; j++) {
            if (j > i % 2) break;
            sum += j + 1;
        }
    }
    color = vec4(float(sum) / 24.0, float(n) / 12.0, 0.0, 1.0);
}
