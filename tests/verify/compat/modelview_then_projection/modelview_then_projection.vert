#version 120
varying vec4 e; void main() { e = gl_ModelViewMatrix * gl_Vertex; gl_Position = gl_ProjectionMatrix * e; }
