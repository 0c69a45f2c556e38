#version 330 core
in VS_OUT {
    vec3 normal;
    vec4 worldPos;
} fs_in;

out vec4 FragColor;

void main()
{
    FragColor = vec4(normalize(fs_in.normal) * 0.5 + 0.5, fs_in.worldPos.w);
}
