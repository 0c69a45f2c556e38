#version 120
void main() { gl_FragColor = vec4(gl_LightSource[0].halfVector.xyz * 0.5 + 0.5, 1.0); }
