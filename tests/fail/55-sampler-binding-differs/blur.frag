#version 420 core
in vec2 uv;
layout(binding = 2) uniform sampler2D tex;
out vec4 color;
void main()
{
    color = texture(tex, uv);
}
