#version 330 core
// Finished wood (seed 004): pass the view-space position and tangent frame to the fragment
// stage, which evaluates the Marschner fibre model per pixel.

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexCoord;
layout(location = 3) in vec4 aTangent; // xyz tangent (along u = the grain), w = bitangent sign

uniform mat4 model_view;
uniform mat4 projection;
uniform mat3 normal_matrix; // inverse transpose of model_view (the board is scaled non-uniformly)

out VertexData
{
    vec3 viewPos;
    vec3 viewNormal;
    vec3 viewTangent;
    float tangentSign;
    vec2 uv;
} vs_out;

void main()
{
    vec4 p = model_view * vec4(aPosition, 1.0);
    vs_out.viewPos = p.xyz;
    vs_out.viewNormal = normal_matrix * aNormal;
    vs_out.viewTangent = mat3(model_view) * aTangent.xyz; // tangents transform like positions
    vs_out.tangentSign = aTangent.w;
    vs_out.uv = aTexCoord;
    gl_Position = projection * p;
}
