#version 330 core
// Positions are clip-space already; the normal attribute carries a colour, passed as
// four scaled copies in a block and two weights in an array, which the geometry stage
// reads back at run-time indices.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
out Shades {
    vec3 tint[4];
} shades;
out float weight[2];
void main() {
    for (int i = 0; i < 4; i++) {
        shades.tint[i] = normal * float(i) / 3.0;
    }
    weight[0] = 0.5;
    weight[1] = 1.0;
    gl_Position = vec4(position, 1.0);
}
