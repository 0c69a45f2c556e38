#version 330 core
// Interface blocks naga cannot take as declared: an array member before another member,
// a matrix member, an integer member, and a block without an instance name.
in vec4 position;
out Shading {
    vec3 weights[3];
    float scale;
    mat3 basis;
    flat int band;
} shading;
out Extra {
    vec2 offsets[2];
    vec4 tint;
};
void main() {
    gl_Position = position;
    vec2 p = position.xy * 0.5 + 0.5;
    for (int i = 0; i < 3; i++) {
        shading.weights[i] = vec3(p, float(i) * 0.25);
    }
    shading.scale = p.x + p.y;
    shading.basis = mat3(vec3(p.x, 0.0, 0.0), vec3(0.0, p.y, 0.0), vec3(0.25, 0.5, 0.75));
    shading.band = int(p.x * 4.0);
    offsets[0] = p.yx;
    offsets[1] = vec2(0.125);
    tint = vec4(p, 1.0 - p.x, 1.0);
}
