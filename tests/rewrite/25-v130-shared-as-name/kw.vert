#version 130
in vec2 position;

out float shared;

void main()
{
    shared = position.x * 0.5 + 0.5;
    gl_Position = vec4(position, 0.0, 1.0);
}
