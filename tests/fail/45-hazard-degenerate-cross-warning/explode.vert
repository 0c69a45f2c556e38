#version 420 core
// Seed 000's exploding mesh, vertex stage: positions go to clip space here; the geometry
// stage moves each triangle along its face normal.
layout(location = 0) in vec3 vertexPosition;
layout(location = 1) in vec2 texCoords;

out vert_vars
{
    vec2 outputTexCoords;
} vert_out;

uniform mat4 transform;

void main()
{
    vert_out.outputTexCoords = texCoords;
    gl_Position = transform * vec4(vertexPosition, 1.0);
}
