#version 330 core
// A soft shadow marched from t = 0: the first step divides by t while it is still 0
// (±Inf; NaN where the distance is 0 too). Later steps are safe, so only the first
// iteration, analysed on its own, shows it.
in vec2 uv;
out vec4 color;
uniform sampler2D heights;
float distanceAt(vec2 p) {
    return texture(heights, p).r;
}
void main() {
    float shade = 1.0;
    float t = 0.0;
    for (int i = 0; i < 16; i++) {
        float h = distanceAt(uv + vec2(t, 0.0));
        shade = min(shade, 8.0 * h / t);
        t += clamp(h, 0.02, 0.1);
    }
    color = vec4(vec3(shade), 1.0);
}
