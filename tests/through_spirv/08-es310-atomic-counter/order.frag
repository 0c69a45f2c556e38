#version 310 es
precision highp float;

// Pixels numbered in the order they are shaded, with GLSL ES 3.10's atomic counters.
layout(binding = 0, offset = 0) uniform atomic_uint shaded;

layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;

void main()
{
    uint order = atomicCounterIncrement(shaded);
    color = vec4(uv, float(order % 256u) / 255.0, 1.0);
}
