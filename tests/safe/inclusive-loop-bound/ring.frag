#version 150
// Loops ended by `!=` and by a float comparison of the counter: both bound the counter
// (no W0719).
in vec3 color;
out vec4 frag;
const float steps = 4.0;
void main() {
    vec3 c = color;
    for (int i = 0; i != 3; ++i) {
        c *= 0.9;
    }
    for (int i = 0; float(i) < steps; i++) {
        c += vec3(0.01);
    }
    frag = vec4(c, 1.0);
}
