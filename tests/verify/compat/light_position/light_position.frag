#version 120
void main() { gl_FragColor = gl_LightSource[0].position * 0.5 + 0.25; }
