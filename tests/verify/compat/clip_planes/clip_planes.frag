#version 120
void main() { gl_FragColor = gl_ClipPlane[0] + gl_ClipPlane[5] + vec4(0.5); }
