#version 330 core
in Shading {
    vec3 weights[3];
    float scale;
    mat3 basis;
    flat int band;
} shading;
in Extra {
    vec2 offsets[2];
    vec4 tint;
};
out vec4 color;
void main() {
    int k = int(gl_FragCoord.x) % 3;
    vec3 w = shading.weights[k] * shading.scale * 0.5;
    vec3 b = shading.basis * vec3(1.0, 1.0, 0.5);
    color = vec4(mix(w, b, 0.5) * tint.rgb + vec3(offsets[1].x * float(shading.band), offsets[0]), 1.0);
}
