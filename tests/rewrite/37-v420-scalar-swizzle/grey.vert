#version 420 core
layout(location = 0) in vec3 aPos;
out float height;
void main()
{
    height = aPos.y * 0.5 + 0.5;
    gl_Position = vec4(aPos, 1.0);
}
