#version 120
// The second shader object of the vertex stage: GL links it with two_units.vert.
varying vec4 lit;
vec4 light(vec3 n, vec4 eye) {
    vec3 l = normalize(gl_LightSource[0].position.xyz - eye.xyz * gl_LightSource[0].position.w);
    return gl_FrontLightModelProduct.sceneColor + gl_FrontLightProduct[0].diffuse * max(dot(n, l), 0.0);
}
