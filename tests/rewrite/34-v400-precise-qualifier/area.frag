#version 400
in vec2 uv;
out vec4 fragColor;

void main()
{
    precise float a = uv.x * uv.y + uv.x;
    fragColor = vec4(a, uv, 1.0);
}
