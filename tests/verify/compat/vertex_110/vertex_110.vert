void main() { gl_FrontColor = vec4(gl_Vertex.xyz * 0.5 + 0.5, 1.0); gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }
