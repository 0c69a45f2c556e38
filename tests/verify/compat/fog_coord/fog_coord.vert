#version 120
void main() { gl_FogFragCoord = gl_FogCoord + gl_Vertex.x * 0.5 + 0.5; gl_Position = ftransform(); }
