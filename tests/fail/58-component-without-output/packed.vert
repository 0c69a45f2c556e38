#version 440 core
layout(location = 0) in vec2 aPos;
layout(location = 0) out vec3 vColor;
layout(location = 1, component = 3) out float vAlpha;
void main()
{
    vColor = vec3(aPos, 0.5);
    vAlpha = 0.5;
    gl_Position = vec4(aPos, 0.0, 1.0);
}
