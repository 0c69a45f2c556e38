#version 130
out vec3 p; void main() { p = gl_Vertex.xyz; gl_TexCoord[0] = gl_MultiTexCoord0; gl_Position = ftransform(); }
