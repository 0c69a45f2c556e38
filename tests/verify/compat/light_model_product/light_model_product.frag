#version 120
void main() { gl_FragColor = gl_FrontLightModelProduct.sceneColor * 3.0 + gl_BackLightModelProduct.sceneColor * 0.5; }
