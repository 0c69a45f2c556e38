#version 420 core
// Exploding mesh, geometry stage: every triangle moves along its own face normal by an
// amount that swings between 0 and `intensity` with time, so the mesh flies apart into its
// triangles and comes back together once per 2π seconds. Guarded where the original was
// not: the phase wraps before `sin` (large times), and a zero-area triangle stays put.

in vert_vars
{
    vec2 outputTexCoords;
} geom_in[];

out geom_vars // read by the fragment stage as `in geom_vars { … } frag_in`
{
    vec2 geomTexCoords;
} geom_out;

uniform float timeVar; // seconds

layout (triangles) in;
layout (triangle_strip, max_vertices = 3) out;

// Pushes one corner along the face normal.
vec4 explode(vec4 position, vec3 normal)
{
    float intensity = 7.0;
    float phase = mod(timeVar, 6.2831853);
    vec3 explodeDirection = normal * ((sin(phase) + 1.0) / 2.0) * intensity;
    return position + vec4(explodeDirection, 0.0);
}

// The face normal from the clip-space corners (zero-area triangles have none).
vec3 GetNormal()
{
    vec3 firstVec = vec3(gl_in[0].gl_Position) - vec3(gl_in[1].gl_Position);
    vec3 secondVec = vec3(gl_in[2].gl_Position) - vec3(gl_in[1].gl_Position);
    vec3 normal = cross(firstVec, secondVec);
    return normal * inversesqrt(max(dot(normal, normal), 1e-12));
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
