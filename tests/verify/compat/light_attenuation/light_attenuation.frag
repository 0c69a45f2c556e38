#version 120
void main() { gl_FragColor = vec4(gl_LightSource[3].constantAttenuation * 0.5, gl_LightSource[3].linearAttenuation + 0.25, gl_LightSource[3].quadraticAttenuation + 0.75, 1.0); }
