#version 420 core
in vec2 uv;

uniform sampler2D image;

out vec4 fragColor;

void main()
{
    fragColor = texture2D(image, uv);
}
