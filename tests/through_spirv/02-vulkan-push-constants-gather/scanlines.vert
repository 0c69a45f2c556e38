#version 450
// A full-screen pass in Vulkan GLSL: push constants, a uniform block and a combined
// image sampler, as emulator shader packs write them.
layout(push_constant) uniform Push {
    vec4 SourceSize;
    float Strength;
} params;

layout(std140, set = 0, binding = 0) uniform UBO {
    mat4 MVP;
} global;

layout(location = 0) in vec4 Position;
layout(location = 1) in vec2 TexCoord;
layout(location = 0) out vec2 vTexCoord;

void main()
{
    gl_Position = global.MVP * Position;
    vTexCoord = TexCoord;
}
