#version 330 core
// Per-pixel Phong renormalizes the interpolated normal. Between a vertex whose normal is +z
// and one whose normal is -z (the mesh's flipped normal) the interpolated vNormal crosses
// the zero vector, and normalize(0) is NaN.
in vec3 vNormal;

out vec4 FragColor;

uniform vec3 lightDir;

void main()
{
    vec3 n = normalize(vNormal);
    float diffuse = max(dot(n, normalize(lightDir)), 0.0);
    FragColor = vec4(vec3(0.2, 0.6, 0.15) * (0.2 + 0.8 * diffuse), 1.0);
}
