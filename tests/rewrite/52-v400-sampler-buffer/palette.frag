#version 400
in vec2 uv;
out vec4 fragColor;

uniform samplerBuffer palette;

void main()
{
    fragColor = texelFetch(palette, int(uv.x * 255.0));
}
