#version 120
void main() { gl_FragColor = vec4(gl_DepthRange.near + 0.25, gl_DepthRange.far * 0.5, gl_DepthRange.diff * 0.75, 1.0); }
