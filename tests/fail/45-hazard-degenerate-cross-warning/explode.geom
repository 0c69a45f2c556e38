#version 420 core
// Seed 000's exploding mesh, geometry stage, as the student wrote it: the face normal is
// normalize(cross(firstVec, secondVec)). A triangle collapsed to a line or a point (a
// modelling tool's sliver, a welded vertex) has parallel edges, the cross product is the
// zero vector, and normalize(0) is NaN: its corners fly off to NaN.
in vert_vars
{
    vec2 outputTexCoords;
} geom_in[];

out geom_vars
{
    vec2 geomTexCoords;
} geom_out;

uniform float timeVar;

layout (triangles) in;
layout (triangle_strip, max_vertices = 3) out;

vec4 explode(vec4 position, vec3 normal)
{
    float intensity = 2.0;
    vec3 explodeDirection = normal * ((sin(timeVar) + 1.0) / 2.0) * intensity;
    return position + vec4(explodeDirection, 0.0);
}

vec3 GetNormal()
{
    vec3 firstVec = vec3(gl_in[0].gl_Position) - vec3(gl_in[1].gl_Position);
    vec3 secondVec = vec3(gl_in[2].gl_Position) - vec3(gl_in[1].gl_Position);
    return normalize(cross(firstVec, secondVec));
}

void main()
{
    vec3 normalVector = GetNormal();

    gl_Position = explode(gl_in[0].gl_Position, normalVector);
    geom_out.geomTexCoords = geom_in[0].outputTexCoords;
    EmitVertex();
    gl_Position = explode(gl_in[1].gl_Position, normalVector);
    geom_out.geomTexCoords = geom_in[1].outputTexCoords;
    EmitVertex();
    gl_Position = explode(gl_in[2].gl_Position, normalVector);
    geom_out.geomTexCoords = geom_in[2].outputTexCoords;
    EmitVertex();
    EndPrimitive();
}
