#version 330 core
// texture() with a LOD bias.
in vec2 uv;
out vec4 color;

uniform sampler2D tex;

void main()
{
    color = texture(tex, uv * 4.0, 1.5);
}
