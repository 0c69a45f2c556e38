#version 120
void main() { gl_FragColor = gl_BackLightProduct[0].diffuse * 0.75 + gl_BackLightProduct[0].ambient; }
