#version 120
uniform int n = 3; uniform bool on = true; uniform ivec2 m = ivec2(2, 5); uniform mat2 r = mat2(0.5, 0.25, 0.125, 1.0);
void main() { gl_FragColor = vec4(float(n) / 4.0, on ? 0.75 : 0.0, float(m.y - m.x) / 4.0, r[1][1] * r[0][0] + r[1][0]); }
