#version 330 core
in vec2 uv;
out vec4 fragColor;
void main()
{
    float s = sqrt(uv.x - 0.5); // NaN where uv.x < 0.5
    fragColor = vec4(s, 1.0 / (uv.y - uv.y), 0.0, 1.0); // +Inf in green everywhere
}
