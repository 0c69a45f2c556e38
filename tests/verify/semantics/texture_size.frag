#version 330 core
// textureSize of the placeholder and of its mip levels.
in vec2 uv;
out vec4 color;

uniform sampler2D tex;

void main()
{
    ivec2 s0 = textureSize(tex, 0);
    ivec2 s2 = textureSize(tex, 2);
    color = vec4(float(s0.x) / 512.0, float(s0.y) / 512.0, float(s2.x) / 128.0, 1.0);
}
