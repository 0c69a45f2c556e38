#version 120
void main() { gl_TexCoord[1] = gl_MultiTexCoord3 + vec4(0.25); gl_Position = ftransform(); }
