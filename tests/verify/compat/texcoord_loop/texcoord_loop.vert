#version 120
varying vec4 gl_TexCoord[3]; void main() { for (int i = 0; i < 3; i++) gl_TexCoord[i] = gl_MultiTexCoord0 * float(i + 1) * 0.3; gl_Position = ftransform(); }
