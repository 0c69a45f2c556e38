#version 120
varying vec4 gl_TexCoord[2]; uniform int which = 1; void main() { gl_FragColor = vec4(gl_TexCoord[which].st, 0.5, 1.0); }
