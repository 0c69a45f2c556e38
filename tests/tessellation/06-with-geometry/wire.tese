#version 410 core
layout(triangles, equal_spacing, ccw) in;
in vec3 point[];
out vec3 tessCoord;
void main() {
    tessCoord = gl_TessCoord;
    gl_Position = vec4(gl_TessCoord.x * point[0] + gl_TessCoord.y * point[1] + gl_TessCoord.z * point[2], 1.0);
}
