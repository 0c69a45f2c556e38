#version 420 core
layout(location = 0) in vec3 vertPosition;
layout(location = 1) in vec2 vertTexCoords;

out SurfaceData {
    vec2 texCoords;
    vec3 worldPos;
} vert_out;

uniform mat4 model;
uniform mat4 viewProj;

void main()
{
    vec4 world = model * vec4(vertPosition, 1.0);
    vert_out.texCoords = vertTexCoords;
    vert_out.worldPos = world.xyz;
    gl_Position = viewProj * world;
}
