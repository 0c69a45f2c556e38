#version 120
void main() { gl_FragColor = vec4(gl_LightSource[2].spotDirection * 0.5 + 0.5, gl_LightSource[2].spotCutoff / 360.0) + vec4(gl_LightSource[2].spotExponent, gl_LightSource[2].spotCosCutoff * 0.25, 0.0, 0.0); }
