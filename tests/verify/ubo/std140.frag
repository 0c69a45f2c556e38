#version 330
// The user's own uniform blocks with members WGSL cannot hold as declared (bools, arrays of
// scalars and 2-vectors: std140 strides them to 16 bytes), read by name and by instance.
layout(std140) uniform Flags {
    bool r;
    bvec2 gb;
    float weights[4];
    vec2 offsets[2];
    bool on[2];
};
uniform Params {
    float f[3];
    bool use_f;
} params;
// Structs smaller than std140's 16-byte struct alignment, nested, between other members
// (naga aligns a struct to its largest member; effectc adds std140's gaps as fillers).
struct Tint { float r; };
struct Shade { Tint tint; vec2 gb; float a; };
uniform Shading {
    float gain;
    Shade shade;
    float bias;
} shading;
out vec4 color;
void main() {
    int k = int(gl_FragCoord.x) % 3;
    float w = weights[k] + params.f[k] + params.f.length() * 0.01;
    float[4] all_w = weights;
    float s = shading.shade.tint.r * shading.gain + shading.shade.gb.y + shading.shade.a + shading.bias;
    color = vec4(r ? 1.0 : 0.25, gb.x ? 0.5 : 0.0, (w + all_w[3] + offsets[1].y) * 0.5 + s, (on[1] && params.use_f) ? 1.0 : 0.5);
}
