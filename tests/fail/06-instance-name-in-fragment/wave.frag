#version 410 core
in VertexData {
    vec3 color;
    float height;
} frag_in;

out vec4 fragColor;

void main()
{
    fragColor = vec4(vert_out.color * (0.8 + vert_out.height), 1.0);
}
