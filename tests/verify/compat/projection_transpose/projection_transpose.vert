#version 120
varying vec4 c; void main() { c = gl_ProjectionMatrixTranspose * gl_Vertex; gl_Position = ftransform(); }
