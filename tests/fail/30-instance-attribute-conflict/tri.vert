#version 330 core
layout(location = 0) in vec3 p0;
layout(location = 1) in vec2 t0;
out vec2 uv;
uniform mat4 mvp;
void main()
{
    uv = t0;
    gl_Position = mvp * vec4(p0, 1.0);
}
