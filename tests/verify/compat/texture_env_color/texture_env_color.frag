#version 120
void main() { gl_FragColor = gl_TextureEnvColor[0] + vec4(0.3, 0.6, 0.9, 1.0); }
