#version 120
void main() { gl_FrontSecondaryColor = gl_SecondaryColor + vec4(0.25, 0.5, 0.75, 0.0); gl_Position = ftransform(); }
