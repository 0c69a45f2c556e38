#version 150
// Interface-block members declared without a size, in both stages: GL's linker sizes each
// by the largest constant index any stage uses (`tint[2]` → 3, `lift[1]` → 2); an array
// member before another member and a block without an instance name among them.
in vec4 position;
out Carried {
    float tint[];
    vec2 lift[];
} carried;
out Bare {
    float shade[];
};
void main() {
    gl_Position = position;
    vec2 p = position.xy * 0.5 + 0.5;
    carried.tint[0] = p.x;
    carried.tint[2] = p.y;
    carried.lift[1] = p * 0.25;
    shade[1] = 0.75 - p.x * 0.5;
}
