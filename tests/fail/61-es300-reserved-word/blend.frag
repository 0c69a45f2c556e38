#version 300 es
precision highp float;
in vec2 uv;
out vec4 color;

void main()
{
    // `filter` is reserved for future use in GLSL ES 3.00.
    float filter = uv.x * 0.5;
    color = vec4(filter, uv.y, 0.0, 1.0);
}
