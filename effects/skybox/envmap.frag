#version 330 core
// Environment-mapped object, fragment stage (seed 000): the ray from the camera to the
// surface is reflected around the normal and refracted through it; both look up the same
// cube map the skybox shows, through the same environment() function. A Fresnel term
// blends refraction (facing the camera) into reflection (grazing angles), with a tint
// for the glassy body.

in vec3 worldPos;
in vec3 worldNormal;

out vec4 FragColor;

uniform vec3 cameraPos;
uniform samplerCube skybox;
uniform float refractiveIndex;  // ratio n1/n2 for refract(), air into the object
uniform float reflectivity;     // reflection at normal incidence (Fresnel F0)
uniform vec3 tint;              // colour multiplied into the refracted light
uniform vec3 groundColour;      // the skybox's colour below the horizon

vec3 safeNormalize(vec3 v)
{
    return v * inversesqrt(max(dot(v, v), 1e-12));
}

// The skybox's look-up (skybox.frag): cube map, darkened below the horizon.
vec3 environment(vec3 dir)
{
    vec3 sky = texture(skybox, dir).rgb;
    float up = dir.y * inversesqrt(max(dot(dir, dir), 1e-12));
    float ground = smoothstep(0.02, -0.08, up);
    return mix(sky, groundColour * (0.4 + 0.8 * sky), ground);
}

void main()
{
    vec3 N = safeNormalize(worldNormal);
    vec3 I = safeNormalize(worldPos - cameraPos);

    vec3 R = reflect(I, N);
    vec3 T = refract(I, N, refractiveIndex);
    vec3 reflected = environment(R);
    // refract() returns 0 on total internal reflection; fall back to the reflection.
    vec3 refracted = dot(T, T) > 0.0 ? environment(T) * tint : reflected;

    float cosTheta = clamp(dot(-I, N), 0.0, 1.0);
    float fresnel = reflectivity + (1.0 - reflectivity) * pow(1.0 - cosTheta, 5.0);

    FragColor = vec4(mix(refracted, reflected, clamp(fresnel, 0.0, 1.0)), 1.0);
}
