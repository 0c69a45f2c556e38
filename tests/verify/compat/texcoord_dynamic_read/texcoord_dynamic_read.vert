#version 120
varying vec4 gl_TexCoord[2]; void main() { gl_TexCoord[0] = vec4(0.2); gl_TexCoord[1] = gl_MultiTexCoord0; gl_Position = ftransform(); }
