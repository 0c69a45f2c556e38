#version 120
varying vec4 c; void main() { c = gl_ModelViewMatrixInverseTranspose * vec4(gl_Normal, 0.0); gl_Position = ftransform(); }
