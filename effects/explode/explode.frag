#version 420
// Exploding mesh, fragment stage: the mesh's texture, nothing else.

in geom_vars
{
    vec2 geomTexCoords;
} frag_in;

layout (location = 0) out vec4 fragcolor;

uniform sampler2D diffuseVar;

void main()
{
    fragcolor = texture(diffuseVar, frag_in.geomTexCoords);
}
