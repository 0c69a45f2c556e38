#version 120
varying vec4 p; void main() { p = gl_Vertex; gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }
