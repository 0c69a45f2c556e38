#version 330 core
// Counts and sums a loop with constant bounds always adds to, an angle stepped with the
// loop's counter, and a ternary on a constant: none of them can reach the hazard.
in vec2 uv;
out vec4 color;
uniform sampler2D image;
vec3 tangentOf(vec3 n) {
    vec3 up = abs(n.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    return normalize(cross(up, n));
}
void main() {
    float shadow = 0.0;
    int count = 0;
    for (int x = -1; x <= 1; x++) {
        for (int y = -1; y <= 1; y++) {
            shadow += texture(image, uv + vec2(x, y) * 0.01).r;
            count++;
        }
    }
    float weights = 0.0;
    vec3 sum = vec3(0.0);
    for (int i = -4; i <= 4; i++) {
        float w = exp(-float(i * i) / 8.0);
        sum += texture(image, uv + vec2(float(i) * 0.01, 0.0)).rgb * w;
        weights += w;
    }
    float occlusion = 0.0;
    float angle = 0.0;
    for (int i = 0; i < 8; ++i, angle += 0.785398) {
        occlusion += texture(image, uv + vec2(cos(angle), sin(angle)) * 0.02).a;
    }
    vec3 t = tangentOf(vec3(0.0, 0.0, 1.0));
    color = vec4(sum / weights * (shadow / float(count)) + t * 0.0, occlusion / 8.0);
}
