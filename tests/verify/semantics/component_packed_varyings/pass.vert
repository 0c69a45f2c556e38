#version 440
// Varyings packed into one location's components (`layout(location = L, component = C)`),
// matched by location across stages whose names differ: WGSL has no components, so each
// packed pair takes a location of its own in every stage, and the geometry fold still finds
// them.
in vec4 position;
layout(location = 0) out vec3 base;
layout(location = 0, component = 3) out float alpha;
layout(location = 1) out vec2 low;
layout(location = 1, component = 2) out vec2 high;
void main() {
    gl_Position = position;
    vec2 p = position.xy * 0.5 + 0.5;
    base = vec3(p, 0.25);
    alpha = 1.0 - p.x * 0.5;
    low = p.yx * 0.5;
    high = vec2(0.125, p.y * 0.75);
}
