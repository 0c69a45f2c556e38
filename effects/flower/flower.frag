#version 330 core
// Flower: per-pixel Phong shading of the bent flower (seed 004, task 1), two-sided so the
// inside of the cup is lit too; green stem, petals shading from a yellow heart to pink.

in FlowerData
{
    vec3 worldPos;
    vec3 worldNormal;
    vec3 worldLight;
    float height;
    float petal;
} fs_in;

out vec4 FragColor;

uniform vec3 camera_position;
uniform float shininess;

vec3 safeNormalize(vec3 v, vec3 fallback)
{
    float len = length(v);
    return len > 1e-6 ? v / len : fallback;
}

void main()
{
    vec3 n = safeNormalize(fs_in.worldNormal, vec3(0.0, 1.0, 0.0));
    vec3 v = safeNormalize(camera_position - fs_in.worldPos, vec3(0.0, 0.0, 1.0));
    if (dot(n, v) < 0.0)
    {
        n = -n; // seen from the back (inside of the cup)
    }
    vec3 l = safeNormalize(fs_in.worldLight - fs_in.worldPos, vec3(0.0, 1.0, 0.0));
    vec3 h = safeNormalize(l + v, n);

    vec3 stem = vec3(0.12, 0.5, 0.12);
    vec3 heart = vec3(1.0, 0.8, 0.15);
    vec3 petalTip = vec3(1.0, 0.35, 0.62);
    vec3 petalColour = mix(heart, petalTip, smoothstep(0.05, 0.45, fs_in.petal));
    vec3 albedo = mix(stem, petalColour, smoothstep(0.0, 0.04, fs_in.petal));

    float ndl = dot(n, l);
    float diffuse = max(ndl, 0.0);
    float wrap = 0.5 + 0.5 * ndl; // soft fill so the shadowed side keeps its shape
    float specular = ndl > 0.0 ? pow(max(dot(n, h), 0.0), shininess) : 0.0;
    vec3 colour = albedo * (0.25 + 0.35 * wrap * wrap + 0.7 * diffuse) + vec3(0.4) * specular;
    FragColor = vec4(colour, 1.0);
}
