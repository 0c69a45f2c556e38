#version 420 core

// Pixels numbered in the order they are shaded, with GL 4.20's atomic counters (naga's
// GLSL front has none; glslang's relaxed Vulkan rules make the counter a storage buffer).
layout(binding = 0, offset = 0) uniform atomic_uint shaded;

uniform float exposure;

layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;

void main()
{
    uint order = atomicCounterIncrement(shaded);
    float ev = log(exposure);
    color = vec4(uv * ev, float(order % 256u) / 255.0, 1.0);
}
