#version 120
uniform float k = 0.25; uniform vec3 c = vec3(0.1, 0.5, 0.9); uniform float w[2] = float[2](0.3, 0.7);
void main() { gl_FragColor = vec4(c.r + k, c.g * w[0], c.b * w[1], 1.0); }
