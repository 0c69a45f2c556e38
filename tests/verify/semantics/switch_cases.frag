#version 330 core
// switch with negative labels, a shared body, default in the middle.
in vec2 uv;
out vec4 color;

void main()
{
    int k = int(gl_FragCoord.x) / 8 - 3;
    float r = 0.0;
    switch (k) {
    case -3:
        r = 0.1;
        break;
    case -1:
    case 1:
        r = 0.4;
        break;
    default:
        r = 0.7;
        break;
    case 4:
        r = 1.0;
        break;
    }
    color = vec4(r, float(k + 3) / 8.0, 0.0, 1.0);
}
