#version 330 core
smooth in float vId;

out vec4 FragColor;

void main()
{
    FragColor = vec4(vec3(fract(vId * 0.1)), 1.0);
}
