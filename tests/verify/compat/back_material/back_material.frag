#version 120
void main() { gl_FragColor = gl_BackMaterial.diffuse * 0.75 + gl_BackMaterial.ambient * 0.5; }
