#version 330 core
in vec2 uv;
flat in int instance;

out vec4 fragColor;

void main()
{
    fragColor = vec4(uv, float(instance) * 0.25, 1.0);
}
