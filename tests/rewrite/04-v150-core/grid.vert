#version 150 core
in vec3 position;

uniform mat4 mvp;

out vec3 worldPos;

void main()
{
    worldPos = position;
    gl_Position = mvp * vec4(position, 1.0);
}
