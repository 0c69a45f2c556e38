#version 150
flat in int id;
out vec4 color;

void main()
{
    color = vec4(float(id & 1), 0.0, 0.0, 1.0);
}
