#version 420
// Exploding mesh, vertex stage (seed 000, "Shader Coursework": the first of its three
// shaders). Positions go to clip space here; the geometry stage pushes each triangle apart.

uniform mat4 transform; // model-view-projection, set by the application each frame

layout (location = 0) in vec3 vertexPosition;
layout (location = 1) in vec2 texCoords;

out vert_vars // what the geometry stage reads, as `in vert_vars { … } geom_in[]`
{
    vec2 outputTexCoords;
} vert_out;

void main()
{
    vert_out.outputTexCoords = texCoords;
    gl_Position = transform * vec4(vertexPosition, 1.0);
}
