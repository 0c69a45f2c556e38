#version 330 core
// Only the chosen arm of ?: is evaluated.
in vec2 uv;
out vec4 color;

float counter = 0.0;
float bump(float x) { counter += 1.0; return x; }

void main()
{
    float v = uv.x > 0.5 ? bump(uv.x) : uv.y;
    float w = uv.y > 0.5 ? uv.x : bump(uv.y);
    color = vec4(v, w, counter / 2.0, 1.0);
}
