#version 120
varying vec4 c; void main() { c = gl_ProjectionMatrixInverse * ftransform(); gl_Position = ftransform(); }
