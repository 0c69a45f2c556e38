#version 120
varying vec3 normal; varying vec3 eye;
void main() {
    vec3 n = normalize(normal);
    vec3 l = normalize(gl_LightSource[0].position.xyz - eye * gl_LightSource[0].position.w);
    float diffuse = max(dot(n, l), 0.0);
    vec3 r = reflect(-l, n);
    float spec = pow(max(dot(r, normalize(-eye)), 0.0), 8.0);
    vec4 checker = vec4(mod(floor(gl_TexCoord[0].s * 4.0) + floor(gl_TexCoord[0].t * 4.0), 2.0));
    gl_FragColor = gl_FrontMaterial.diffuse * diffuse * (0.5 + 0.5 * checker) + vec4(spec * 0.5) + gl_LightModel.ambient;
}
