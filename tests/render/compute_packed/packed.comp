#version 430
// A compute-only program that stores to an image of a packed format WebGPU's core cannot
// store to (`rgb10_a2`; GL can): `render` stores to it where the adapter can.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgb10_a2, binding = 0) writeonly uniform image2D packed;
void main() {
    imageStore(packed, ivec2(gl_GlobalInvocationID.xy), vec4(1.0, 0.0, 0.5, 1.0));
}
