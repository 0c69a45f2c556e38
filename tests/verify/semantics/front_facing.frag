#version 330 core
// gl_FrontFacing of a counter-clockwise triangle.
in vec2 uv;
out vec4 color;

void main()
{
    color = vec4(float(gl_FrontFacing), uv, 1.0);
}
