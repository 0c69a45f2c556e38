#version 120
varying vec4 c; void main() { c = gl_ModelViewMatrixInverse * (gl_ModelViewMatrix * gl_Vertex); gl_Position = ftransform(); }
