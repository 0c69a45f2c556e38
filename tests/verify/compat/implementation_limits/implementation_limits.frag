#version 120
void main() { gl_FragColor = vec4(float(gl_MaxLights) / 16.0, float(gl_MaxClipPlanes) / 32.0, float(gl_MaxTextureCoords) / 64.0, float(gl_MaxTextureUnits) / 8.0); }
