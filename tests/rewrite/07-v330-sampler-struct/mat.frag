#version 330 core
struct Material {
    sampler2D diffuse;
    sampler2D specular;
    float shininess;
};

in vec2 vUv;

uniform Material material;

out vec4 FragColor;

vec3 sampleMap(sampler2D map, vec2 uv)
{
    return texture(map, uv).rgb;
}

void main()
{
    vec3 d = sampleMap(material.diffuse, vUv);
    vec3 s = sampleMap(material.specular, vUv);
    FragColor = vec4(d + s * material.shininess * 0.01, 1.0);
}
