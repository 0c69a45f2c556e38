#version 330 core
// Seed 002's Phong, fragment stage, as the tutorial writes it: normalize(Normal) is
// 0 / 0 when the mesh's normal is zero (a degenerate face's, or a broken export).
in vec3 FragPos;
in vec3 Normal;

out vec4 FragColor;

uniform vec3 lightPos;
uniform vec3 viewPos;

void main()
{
    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(lightPos - FragPos);
    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 reflectDir = reflect(-lightDir, norm);
    float diff = max(dot(norm, lightDir), 0.0);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), 32.0);
    vec3 color = vec3(0.1) + diff * vec3(0.8, 0.4, 0.3) + 0.5 * spec;
    FragColor = vec4(color, 1.0);
}
