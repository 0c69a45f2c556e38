#version 330 core
// Parallax occlusion mapping, vertex stage (seed 002): builds the TBN frame from normal + tangent and
// moves the camera, light and fragment positions into tangent space (the seed's
// v.x = dot(pos, t); v.y = dot(pos, b); v.z = dot(pos, n)).

layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexCoords;
layout(location = 3) in vec4 aTangent;

out VS_OUT
{
    vec2 TexCoords;
    vec3 TangentViewPos;
    vec3 TangentLightPos;
    vec3 TangentFragPos;
} vs_out;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform vec3 viewPos;
uniform vec3 lightPos;
uniform float uvScale;

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
    T = safeNormalize(T - dot(T, N) * N);
    vec3 B = cross(N, T) * (aTangent.w < 0.0 ? -1.0 : 1.0);
    // Orthonormal, so the inverse (world -> tangent) is the transpose.
    mat3 worldToTangent = transpose(mat3(T, B, N));

    vs_out.TexCoords = aTexCoords * uvScale;
    vs_out.TangentViewPos = worldToTangent * viewPos;
    vs_out.TangentLightPos = worldToTangent * lightPos;
    vs_out.TangentFragPos = worldToTangent * worldPos.xyz;
    gl_Position = projection * view * worldPos;
}
