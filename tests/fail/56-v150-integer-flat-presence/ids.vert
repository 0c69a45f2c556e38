#version 150
// An integer output without `flat`, read as a `flat` input: the same value either way,
// but before GLSL 4.30 the qualifiers' presence must match, and Mesa refuses the link.
in vec2 position;
out int id;

void main()
{
    id = gl_VertexID;
    gl_Position = vec4(position, 0.0, 1.0);
}
