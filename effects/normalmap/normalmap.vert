#version 330 core
// Normal mapping, vertex stage (seed 002): builds the tangent frame (TBN) in world space
// from the mesh normal and tangent (xyz = tangent, w = handedness of the bitangent).

layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexCoords;
layout(location = 3) in vec4 aTangent;

out VS_OUT
{
    vec3 FragPos;
    vec2 TexCoords;
} vs_out;
out mat3 TBN; // tangent space -> world space (a plain varying: effectc cannot yet split a matrix member of an interface block)

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform float uvScale; // texture tiling

vec3 safeNormalize(vec3 v)
{
    return v * inversesqrt(max(dot(v, v), 1e-12));
}

void main()
{
    vec4 worldPos = model * vec4(aPos, 1.0);
    // Rotation + uniform scale only: mat3(model) transforms normals and tangents alike.
    mat3 m = mat3(model);
    vec3 N = safeNormalize(m * aNormal);
    vec3 T = safeNormalize(m * aTangent.xyz);
    T = safeNormalize(T - dot(T, N) * N);              // Gram-Schmidt re-orthogonalise
    vec3 B = cross(N, T) * (aTangent.w < 0.0 ? -1.0 : 1.0); // handedness from w

    vs_out.FragPos = worldPos.xyz;
    vs_out.TexCoords = aTexCoords * uvScale;
    TBN = mat3(T, B, N);
    gl_Position = projection * view * worldPos;
}
