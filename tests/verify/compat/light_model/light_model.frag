#version 120
void main() { gl_FragColor = gl_LightModel.ambient * 2.0; }
