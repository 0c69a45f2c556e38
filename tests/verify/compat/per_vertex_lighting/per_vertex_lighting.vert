#version 120
void main() {
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    vec3 l = normalize(gl_LightSource[0].position.xyz);
    float d = max(dot(n, l), 0.0);
    vec3 h = normalize(gl_LightSource[0].halfVector.xyz);
    float s = pow(max(dot(n, h), 0.0), 16.0);
    gl_FrontColor = gl_FrontLightModelProduct.sceneColor + gl_FrontLightProduct[0].ambient
        + gl_FrontLightProduct[0].diffuse * d + vec4(0.3) * s;
    gl_Position = ftransform();
}
