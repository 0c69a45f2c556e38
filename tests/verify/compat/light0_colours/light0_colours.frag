#version 120
void main() { gl_FragColor = vec4(gl_LightSource[0].diffuse.r, gl_LightSource[0].specular.g, gl_LightSource[0].ambient.b + 0.5, 1.0); }
