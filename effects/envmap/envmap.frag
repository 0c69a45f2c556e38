#version 330 core
// Environment mapping, fragment stage (seed 000): the incident ray I from the camera to
// the surface is reflected around the world-space normal N and looks up the cube map.
// A Schlick-style Fresnel term makes grazing angles more mirror-like.

in vec3 WorldPos;
in vec3 WorldNormal;

out vec4 FragColor;

uniform vec3 cameraPos;
uniform samplerCube skybox;
uniform float reflectivity;  // 0 = base colour only, 1 = perfect mirror
uniform vec3 baseColor;      // colour of the non-reflective part
uniform float fresnelPower;  // exponent of the Fresnel falloff

// normalize() that cannot divide by zero: a zero vector stays (almost) zero.
vec3 safeNormalize(vec3 v)
{
    return v * inversesqrt(max(dot(v, v), 1e-12));
}

void main()
{
    vec3 N = safeNormalize(WorldNormal);
    vec3 I = safeNormalize(WorldPos - cameraPos);
    vec3 R = reflect(I, N);

    vec3 envColor = texture(skybox, R).rgb;

    float cosTheta = clamp(dot(-I, N), 0.0, 1.0);
    float fresnel = reflectivity + (1.0 - reflectivity) * pow(1.0 - cosTheta, max(fresnelPower, 0.5));

    vec3 color = mix(baseColor, envColor, clamp(fresnel, 0.0, 1.0));
    FragColor = vec4(color, 1.0);
}
