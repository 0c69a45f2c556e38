#version 420 core
in vec3 position;
layout(binding = 1) uniform sampler2D tex;
out vec2 uv;
void main()
{
    uv = position.xy;
    gl_Position = vec4(position + texture(tex, uv).rgb, 1.0);
}
