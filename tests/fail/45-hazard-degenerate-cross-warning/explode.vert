#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform float explodeAmount; // how far each face is pushed out along its normal

out vec3 vWorldPos;

void main()
{
    // the cube has flat normals: every face moves out as one piece, as in the seed's explode
    vec4 world = model * vec4(aPos + aNormal * explodeAmount, 1.0);
    vWorldPos = world.xyz;
    gl_Position = projection * view * world;
}
