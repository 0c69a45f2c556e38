#version 420 core
in geom_vars
{
    vec2 geomTexCoords;
} frag_in;

out vec4 FragColor;

void main()
{
    FragColor = vec4(frag_in.geomTexCoords, 0.5, 1.0);
}
