#version 120
void main() { gl_FragColor = vec4(gl_FogFragCoord, 0.0, 1.0 - gl_FogFragCoord, 1.0); }
