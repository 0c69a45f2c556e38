#version 410 core
layout(triangles) in;
in vec3 point[];
patch in vec3 centre;
out vec3 shade;
void main() {
    vec3 p = gl_TessCoord.x * point[0] + gl_TessCoord.y * point[1] + gl_TessCoord.z * point[2];
    shade = vec3(0.5) + 2.0 * (p - centre);
    gl_Position = vec4(p, 1.0);
}
