#version 120
void main() { gl_FragColor = vec4(gl_TexCoord[0].s, gl_TexCoord[1].t, gl_TexCoord[2].s, 1.0); }
