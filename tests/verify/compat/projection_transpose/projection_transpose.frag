#version 120
varying vec4 c; void main() { gl_FragColor = vec4(fract(c.xyz * 0.37 + 0.5), 1.0); }
