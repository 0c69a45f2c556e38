#version 330 core
// Planet: a unit uv_sphere; the fragment stage needs the object-space direction (for
// longitude/latitude, so the texture turns with the planet) and the world normal (lighting).

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

out VS_OUT
{
    vec3 objectDir;   // object-space position on the unit sphere
    vec3 worldNormal; // world-space normal
} vs_out;

void main()
{
    vs_out.objectDir = aPosition;
    // model has a uniform scale and rotations only, so mat3(model) maps normals correctly
    vs_out.worldNormal = mat3(model) * aNormal;
    gl_Position = projection * view * model * vec4(aPosition, 1.0);
}
