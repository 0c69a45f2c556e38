#version 400
in vec2 uv;
out vec4 fragColor;

uniform sampler2D image;

void main()
{
    vec2 lod = textureQueryLod(image, uv * 64.0);
    fragColor = vec4(lod / 8.0, 0.0, 1.0);
}
