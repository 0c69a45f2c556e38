#version 410 core
layout(triangles, equal_spacing, ccw) in;
in vec3 evaluationPoint[];
patch in vec3 tint;
out vec3 shade;
void main() {
    vec3 p = gl_TessCoord.x * evaluationPoint[0] + gl_TessCoord.y * evaluationPoint[1] + gl_TessCoord.z * evaluationPoint[2];
    // A wave the tessellation follows vertex by vertex: its facets show the pattern.
    p.y += 0.2 * sin(9.0 * p.x);
    shade = tint * (0.5 + 0.5 * sin(40.0 * gl_TessCoord));
    gl_Position = vec4(p, 1.0);
}
