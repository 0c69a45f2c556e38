#version 450 core
#define CHANNEL(block, name) block.name##_channel
in vec4 offsets[3];
in mat2 spin;
flat in ivec2 cells[2];
in Surface {
    vec2 uv[2];
    float weight;
} surface;
struct Mix { float red_channel; };
out vec4 frag;
void main() {
    float sum = 0.0;
    for (int i = 0; i < cells[0].x + 1 && i < 3; i++) {
        sum += offsets[i].x + offsets[i].z * 0.1;
    }
    Mix m = Mix(sum * 0.3);
    vec2 turned = spin * surface.uv[1];
    float cell = float(cells[1].x * 4 + cells[1].y) / 16.0;
    frag = vec4(CHANNEL(m, red), turned.x * 0.5 + cell * 0.5, surface.uv[0].y * 0.5 + surface.weight * 0.5, 1.0);
}
