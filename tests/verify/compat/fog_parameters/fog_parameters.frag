#version 120
void main() { gl_FragColor = vec4(gl_Fog.color.rgb + vec3(gl_Fog.density * 0.25, gl_Fog.start + 0.5, gl_Fog.end * 0.75), gl_Fog.scale); }
