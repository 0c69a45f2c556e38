#version 120
varying vec3 normal; varying vec3 eye;
void main() {
    normal = gl_NormalMatrix * gl_Normal;
    eye = vec3(gl_ModelViewMatrix * gl_Vertex);
    gl_TexCoord[0] = gl_MultiTexCoord0;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
