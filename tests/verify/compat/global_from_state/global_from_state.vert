#version 120
varying vec4 c; void main() { vec4 e = gl_ModelViewMatrix * gl_Vertex; c = vec4(normalize(e.xyz) * 0.5 + 0.5, 1.0); gl_Position = gl_ProjectionMatrix * e; }
