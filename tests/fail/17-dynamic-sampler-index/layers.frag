#version 330 core
in vec2 uv;

uniform sampler2D layers[4];
uniform int layerCount;

out vec4 fragColor;

void main()
{
    vec4 sum = vec4(0.0);
    for (int i = 0; i < layerCount; i++)
        sum += texture(layers[i], uv);
    fragColor = sum / float(layerCount);
}
