#version 430
// A compute-only program that stores to a buffer only: `render` has no image to show.
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Values {
    float values[];
};
void main() {
    values[gl_GlobalInvocationID.x] *= 2.0;
}
