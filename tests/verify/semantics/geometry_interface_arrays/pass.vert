#version 330 core
// A vertex stage whose outputs the geometry stage reads as arrays and blocks: an array
// member before another member, an unnamed block, a matrix, and gl_ClipDistance/gl_PointSize
// read through gl_in[].
in vec4 position;
out Corner {
    vec4 ramp[3];
    float weight;
} corner;
out Plain {
    mat3 frame;
};
out float gl_ClipDistance[2];
void main() {
    gl_Position = position;
    gl_PointSize = 2.0 + position.x;
    gl_ClipDistance[0] = 4.0;
    gl_ClipDistance[1] = position.y + 8.0;
    vec2 p = position.xy * 0.5 + 0.5;
    for (int i = 0; i < 3; i++) {
        corner.ramp[i] = vec4(p, float(i) / 3.0, 1.0);
    }
    corner.weight = p.x;
    frame = mat3(vec3(p, 0.0), vec3(0.0, 1.0, p.y), vec3(0.5));
}
