#version 330 core
// Water surface, fragment stage (seed 001): transparent green water that reflects a
// cube map around the wave normal; a Schlick Fresnel term makes grazing angles both
// more mirror-like and more opaque.

in vec3 WorldPos;
in vec3 WorldNormal;
in vec2 TexCoord;

out vec4 FragColor;

uniform vec3 cameraPos;
uniform samplerCube skybox;
uniform vec3 waterColor;
uniform float reflectivity;
uniform float fresnelPower;
uniform float minAlpha;

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
    float fresnel = clamp(reflectivity + (1.0 - reflectivity) * pow(1.0 - cosTheta, max(fresnelPower, 0.5)), 0.0, 1.0);

    // Soft fade at the lake's edges so the plane does not end in a hard line.
    vec2 edge = min(TexCoord, 1.0 - TexCoord);
    float edgeFade = smoothstep(0.0, 0.06, min(edge.x, edge.y));

    vec3 color = mix(waterColor, envColor, fresnel);
    float alpha = mix(minAlpha, 1.0, fresnel) * 0.9 * edgeFade;
    FragColor = vec4(color, alpha);
}
