#version 330 core
layout(location = 0) in vec2 aPos;

uniform float fade;

out float vFade;

void main()
{
    vFade = fade;
    gl_Position = vec4(aPos, 0.0, 1.0);
}
