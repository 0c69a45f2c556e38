#version 330 core
// Per-pixel Phong as in seed 002's lecture, every guard left out:
//  - pow(dot(R, V), shininess) without max(): the base is negative when R faces away from V;
//  - log(exposure) with exposure ranged down to 0;
//  - sqrt(1.0 - sinT2) of the refracted cosine, with sinT2 past 1 (total internal reflection);
//  - inversesqrt(lightFalloff * dist2) with lightFalloff ranged down to 0.
in vec3 vWorldPos;
in vec3 vNormal;

out vec4 FragColor;

uniform vec3 lightPos;
uniform vec3 camera_position;
uniform float shininess;
uniform float exposure;
uniform float sinT2Scale;
uniform float lightFalloff;

void main()
{
    vec3 N = normalize(vNormal);
    vec3 L = normalize(lightPos - vWorldPos);
    vec3 V = normalize(camera_position - vWorldPos);
    vec3 R = reflect(-L, N);

    float diffuse = max(dot(N, L), 0.0);
    float specular = pow(dot(R, V), shininess);

    // transmitted light through a thin coat: x = sin^2 of the refracted angle, past 1 under
    // total internal reflection
    float x = sinT2Scale;
    float cosT = sqrt(1.0 - x);

    vec3 toLight = lightPos - vWorldPos;
    float dist2 = dot(toLight, toLight);
    float attenuation = inversesqrt(lightFalloff * dist2);

    vec3 colour = (vec3(0.8, 0.3, 0.2) * diffuse * cosT + vec3(specular)) * min(attenuation, 1.0);
    float ev = log(exposure); // exposure in natural-log stops
    FragColor = vec4(colour * exp(ev), 1.0);
}
