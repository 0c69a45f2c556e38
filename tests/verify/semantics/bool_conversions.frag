#version 330 core
// float(bool), int(bool), bool(float), bool(int).
in vec2 uv;
out vec4 color;

void main()
{
    bool a = bool(floor(uv.x * 2.0));
    bool b = bool(int(gl_FragCoord.y) % 3);
    color = vec4(float(a), float(int(b)) * 0.5, float(a != b), 1.0);
}
