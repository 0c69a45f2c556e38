#version 450 core
#define CHANNEL(block, name) block.name##_channel
layout(location = 1) in Surface {
    vec4 colour;
    flat ivec2 cell;
    vec2 far;
    vec3 normal;
} surface;
in Extra {
    float weight;
};
struct Mix { float red_channel; };
out vec4 frag;
void main() {
    Mix m = Mix(surface.colour.r);
    float cells = float(surface.cell.x + surface.cell.y * 4) / 16.0;
    frag = vec4(CHANNEL(m, red), surface.far.x * 0.5 + cells * 0.5, surface.normal.y + weight * 0.25, 1.0);
}
