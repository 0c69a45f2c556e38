#version 120
void main() { gl_FragColor = vec4(gl_TexCoord[0].st, gl_TexCoord[0].q * 0.5, 1.0); }
