#version 330 core
in vec2 uv;

uniform sampler2D image;
uniform float scale;

out vec4 fragColor;

void main()
{
    fragColor = texture(image, (uv - 0.5) / scale + 0.5);
}
