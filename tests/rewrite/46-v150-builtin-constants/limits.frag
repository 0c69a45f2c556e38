#version 150
invariant in vec4 tint;
in float ramp[min(gl_MaxFragmentInputComponents, 4)];
out vec4 color;
void main() {
    color = vec4(tint.rgb * 0.5 + vec3(ramp[1], ramp[2], ramp[3]) * 0.5, 1.0);
}
