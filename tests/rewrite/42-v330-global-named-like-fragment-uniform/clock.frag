#version 330 core
in float vTime;
uniform float time;
out vec4 fragColor;
void main()
{
    fragColor = vec4(vTime + time);
}
