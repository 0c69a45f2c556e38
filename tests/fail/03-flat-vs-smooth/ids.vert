#version 330 core
layout(location = 0) in vec2 aPos;
layout(location = 1) in float aId;

flat out float vId;

void main()
{
    vId = aId;
    gl_Position = vec4(aPos, 0.0, 1.0);
}
