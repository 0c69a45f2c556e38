#version 120
// The vertex stage is two shader objects: this one has main, lighting.vert the helper.
varying vec4 lit;
vec4 light(vec3 n, vec4 eye);
void main() {
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    lit = light(normalize(gl_NormalMatrix * gl_Normal), eye);
    gl_Position = gl_ProjectionMatrix * eye;
}
