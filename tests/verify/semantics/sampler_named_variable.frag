#version 330 core
// `sampler` is a type only in Vulkan GLSL: OpenGL GLSL may name a variable so (naga's GLSL
// front reads the word as a type everywhere, so effectc renames it for naga).
in vec2 uv;
out vec4 color;

uniform sampler2D sampler;

float weight(float x) { float sampler = 0.25; return x * sampler + 0.5; }

void main()
{
    color = texture(sampler, uv * 2.0) * weight(uv.x);
}
