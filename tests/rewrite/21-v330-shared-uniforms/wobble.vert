#version 330 core
layout(location = 0) in vec3 aPos;

uniform mat4 mvp;
uniform float time;
uniform float amplitude;

out float vWave;

void main()
{
    float w = sin(aPos.x * 6.0 + time) * amplitude;
    vWave = w;
    gl_Position = mvp * vec4(aPos + vec3(0.0, w, 0.0), 1.0);
}
