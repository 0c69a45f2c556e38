#version 330 core
// The colour of the primitive the geometry stage numbered.
out vec4 fragColor;
const vec3 palette[4] = vec3[4](vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0), vec3(0.6, 0.8, 0.0));
void main() {
    fragColor = vec4(palette[gl_PrimitiveID % 4], 1.0);
}
