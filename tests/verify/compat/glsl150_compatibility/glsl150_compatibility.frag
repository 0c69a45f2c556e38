#version 150 compatibility
in vec4 c; out vec4 color; void main() { color = c + gl_LightSource[0].diffuse * 0.25; }
