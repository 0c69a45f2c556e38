#version 330 core
in vec3 worldPos;
in vec3 worldNormal;

out vec4 FragColor;

void main()
{
    float shade = 0.5 + 0.5 * worldNormal.y;
    FragColor = vec4(vec3(0.12, 0.5, 0.12) * shade, 1.0);
}
