#version 430
// A compute-only program that stores to a buffer only: `render` shows the words of the
// buffer it stores to (not `Offsets`, which it only reads), each read as the type its place
// holds (a float, then an int, per item).
layout(local_size_x = 64) in;
struct Item {
    float position;
    int index;
};
layout(std430, binding = 0) buffer Offsets {
    float offsets[];
};
layout(std430, binding = 1) buffer Items {
    Item items[];
};
void main() {
    uint i = gl_GlobalInvocationID.x;
    items[i].position = float(i) * 0.5 - 1.0 + offsets[i];
    items[i].index = -int(i);
}
