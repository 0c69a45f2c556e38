#version 400 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

out vec3 vNormal;

void main()
{
    // unit length at every vertex: the mesh's normals are all unit vectors
    vNormal = normalize(mat3(model) * aNormal);
    gl_Position = projection * view * model * vec4(aPos, 1.0);
}
