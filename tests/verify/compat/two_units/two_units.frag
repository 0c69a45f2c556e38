#version 120
varying vec4 lit;
void main() { gl_FragColor = lit; }
