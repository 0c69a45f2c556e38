#version 330 core
in vec2 sample;

uniform float buffer;

out vec4 fragColor;

float scaled(float x)
{
    return x * buffer;
}

void main()
{
    float buffer2 = scaled(sample.x);
    fragColor = vec4(buffer2, sample.y, 0.0, 1.0);
}
