#version 130
in vec3 p; void main() { gl_FragColor = vec4(p * 0.5 + 0.5, 1.0) * 0.5 + gl_TexCoord[0] * 0.5; }
