#version 430 core

layout(location = 0) in vec2 position;
uniform mat3x2 placement;
out vec2 uv;

void main()
{
    uv = position * 0.5 + 0.5;
    gl_Position = vec4(placement * vec3(position, 1.0), 0.0, 1.0);
}
