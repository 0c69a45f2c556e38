#version 120
uniform vec3 uLightDir;
uniform float uShininess;
uniform samplerCube uEnv;

varying vec3 vNormal;
varying vec3 vEye;

void main()
{
    vec3 n = normalize(vNormal);
    vec3 l = normalize(uLightDir);
    vec3 h = normalize(l + normalize(vEye));
    float diff = max(dot(n, l), 0.0);
    float spec = pow(max(dot(n, h), 0.0), uShininess);
    vec3 env = textureCube(uEnv, reflect(-vEye, n)).rgb;
    gl_FragColor = vec4(vec3(diff) + spec + 0.2 * env, 1.0);
}
