#version 330 core
// texture() beyond [0, 1] repeats; orientation: v = 0 is the first row.
in vec2 uv;
out vec4 color;

uniform sampler2D tex;

void main()
{
    color = texture(tex, uv * 2.5 - 0.75);
}
