#version 120
varying vec4 p; void main() { gl_FragColor = vec4(p.xyz * 0.5 + 0.5, 1.0); }
