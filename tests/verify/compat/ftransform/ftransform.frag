#version 120
void main() { gl_FragColor = vec4(0.2, 0.6, 0.9, 1.0); }
