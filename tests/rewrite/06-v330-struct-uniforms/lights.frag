#version 330 core
struct Material {
    vec3 diffuse;
    vec3 specular;
    float shininess;
};

struct PointLight {
    vec3 position;
    vec3 color;
    float radius;
};

in vec3 vNormal;
in vec3 vPos;

uniform Material material;
uniform PointLight lights[4];
uniform vec3 viewPos;

out vec4 FragColor;

void main()
{
    vec3 n = normalize(vNormal);
    vec3 v = normalize(viewPos - vPos);
    vec3 result = vec3(0.0);
    for (int i = 0; i < 4; i++) {
        vec3 l = lights[i].position - vPos;
        float att = clamp(1.0 - length(l) / lights[i].radius, 0.0, 1.0);
        l = normalize(l);
        vec3 h = normalize(l + v);
        float spec = pow(max(dot(n, h), 0.0), material.shininess);
        result += att * lights[i].color * (material.diffuse * max(dot(n, l), 0.0) + material.specular * spec);
    }
    FragColor = vec4(result, 1.0);
}
