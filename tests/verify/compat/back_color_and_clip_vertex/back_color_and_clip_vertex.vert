#version 120
void main() { gl_FrontColor = vec4(0.1, 0.8, 0.3, 1.0); gl_BackColor = vec4(1.0, 0.0, 0.0, 1.0); gl_ClipVertex = gl_ModelViewMatrix * gl_Vertex; gl_Position = ftransform(); }
