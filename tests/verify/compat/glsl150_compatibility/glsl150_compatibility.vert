#version 150 compatibility
out vec4 c; void main() { c = gl_Color * 0.5 + vec4(gl_Normal * 0.25, 0.0); gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }
