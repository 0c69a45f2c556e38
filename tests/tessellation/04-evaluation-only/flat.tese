#version 410 core
// No control stage: the patch is the draw's triangle, the levels GL's defaults (1.0).
layout(triangles, fractional_odd_spacing, cw) in;
in vec3 colour[];
out vec3 shade;
void main() {
    shade = gl_TessCoord.x * colour[0] + gl_TessCoord.y * colour[1] + gl_TessCoord.z * colour[2];
    gl_Position = gl_TessCoord.x * gl_in[0].gl_Position + gl_TessCoord.y * gl_in[1].gl_Position + gl_TessCoord.z * gl_in[2].gl_Position;
}
