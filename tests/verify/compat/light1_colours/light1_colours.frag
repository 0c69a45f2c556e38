#version 120
void main() { gl_FragColor = gl_LightSource[1].diffuse + gl_LightSource[1].specular * 0.5 + vec4(0.25); }
