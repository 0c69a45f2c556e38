#version 120
varying vec4 c; void main() { c = gl_TextureMatrixInverse[0] * gl_Vertex + gl_TextureMatrixTranspose[1] * gl_Vertex + gl_TextureMatrixInverseTranspose[2][1]; gl_Position = ftransform(); }
