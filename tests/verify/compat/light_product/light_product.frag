#version 120
void main() { gl_FragColor = gl_FrontLightProduct[0].ambient + gl_FrontLightProduct[0].diffuse * 0.5 + gl_FrontLightProduct[0].specular + gl_FrontLightProduct[1].diffuse; }
