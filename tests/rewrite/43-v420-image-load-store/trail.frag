#version 420 core
in vec2 uv;
out vec4 color;

layout(binding = 0, rgba8) uniform image2D mask;
layout(binding = 1, rgba16f) uniform image2D trail;

void main()
{
    ivec2 texel = ivec2(uv * 255.0);
    vec4 m = imageLoad(mask, texel);
    imageStore(trail, texel, vec4(uv, m.r, 1.0));
    color = vec4(uv, m.g, 1.0);
}
