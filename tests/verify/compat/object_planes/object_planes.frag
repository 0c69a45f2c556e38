#version 120
void main() { gl_FragColor = gl_ObjectPlaneS[3] * 0.75 + gl_ObjectPlaneT[3] * 0.5 + gl_ObjectPlaneR[0] + gl_ObjectPlaneQ[0] + vec4(0.2); }
