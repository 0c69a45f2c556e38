#version 120
void main() { gl_FragColor = gl_FrontMaterial.emission * 0.25 + gl_FrontMaterial.ambient + gl_FrontMaterial.diffuse * 0.5 + gl_FrontMaterial.specular + vec4(gl_FrontMaterial.shininess); }
