#version 120
void main() { gl_FragColor = gl_TexCoord[1]; }
