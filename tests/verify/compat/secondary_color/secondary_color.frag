#version 120
void main() { gl_FragColor = vec4(gl_SecondaryColor.rgb, 1.0); }
