#version 330 core
// step and smoothstep (edges in either order).
in vec2 uv;
out vec4 color;

void main()
{
    color = vec4(step(0.5, uv.x), smoothstep(0.2, 0.8, uv.y), smoothstep(0.0, 1.0, uv.x * uv.y), step(uv.y, uv.x));
}
