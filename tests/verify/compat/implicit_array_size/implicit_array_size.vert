#version 120
// A global array sized by the largest constant index used (GLSL 1.10/1.20), written here
// and read in a function.
vec4 corners[];
varying vec4 c;
vec4 pick() { return corners[0] * 0.5 + corners[2] * 0.25; }
void main() {
    corners[0] = gl_Color;
    corners[2] = vec4(gl_Vertex.xy * 0.5 + 0.5, 0.0, 1.0);
    c = pick();
    gl_Position = gl_Vertex;
}
