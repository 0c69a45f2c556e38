#version 120
// Per-vertex fixed-function lighting with every piece of state the manifest sets.
varying float fog;
void main() {
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    vec4 eye = gl_ModelViewMatrix * gl_Vertex;
    vec3 l = normalize(gl_LightSource[1].position.xyz - eye.xyz * gl_LightSource[1].position.w);
    float d = max(dot(n, l), 0.0);
    float spot = dot(-l, normalize(gl_LightSource[1].spotDirection)) >= gl_LightSource[1].spotCosCutoff ? 1.0 : 0.25;
    gl_FrontColor = gl_FrontLightModelProduct.sceneColor + gl_FrontLightProduct[1].ambient + gl_FrontLightProduct[1].diffuse * d * spot;
    fog = clamp((gl_Fog.end - abs(eye.z)) * gl_Fog.scale, 0.0, 1.0);
    gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;
    gl_Position = ftransform();
}
