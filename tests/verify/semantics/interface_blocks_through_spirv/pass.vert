#version 450 core
// Interface blocks between stages in a program that goes through glslang's SPIR-V (the
// fragment stage pastes tokens with `##`, which naga's GLSL front does not take). Each
// block member is a varying of its own at the location GL gives it: the block's location
// counted on member by member, and for a block without a location, where glslang places it
// for the whole program. (A member's own location is tested on the SPIR-V alone: Mesa
// 22.3 does not link it.)
in vec4 position;
layout(location = 1) out Surface {
    vec4 colour;
    flat ivec2 cell;
    vec2 far;
    vec3 normal;
} surface;
out Extra {
    float weight;
};
void main() {
    gl_Position = position;
    vec2 p = position.xy * 0.5 + 0.5;
    surface.colour = vec4(p, 0.25, 1.0);
    surface.cell = ivec2(p * 4.0);
    surface.far = p.yx;
    surface.normal = vec3(0.5, p.x * 0.5, 0.75);
    weight = p.x * p.y;
}
