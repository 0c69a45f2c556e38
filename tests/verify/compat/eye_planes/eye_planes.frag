#version 120
void main() { gl_FragColor = gl_EyePlaneS[0] * 0.5 + gl_EyePlaneT[0] * 0.25 + gl_EyePlaneR[1] + gl_EyePlaneQ[2] + vec4(0.1); }
