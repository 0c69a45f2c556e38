#version 120
varying vec3 n; void main() { gl_FragColor = vec4(n * 0.5 + 0.5, 1.0); }
