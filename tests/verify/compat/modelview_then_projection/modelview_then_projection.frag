#version 120
varying vec4 e; void main() { gl_FragColor = vec4(fract(e.xyz), 1.0); }
