#version 120
varying vec4 c; vec4 tint() { return gl_FrontMaterial.diffuse; } void main() { gl_FragColor = c * tint(); }
