#version 330 core
in vec4 shade;
out vec4 color;
uniform struct { vec4 tint; vec2 gain; } light;
void main()
{
    color = shade * light.gain.x + light.tint * 0.25;
}
