#version 330 core
flat in int corner;
flat in vec3 tint;
in float perspective;
out vec4 color;

void main()
{
    color = vec4(float(corner) / 2.0 + tint.z, tint.x + tint.y, perspective, 1.0);
}
