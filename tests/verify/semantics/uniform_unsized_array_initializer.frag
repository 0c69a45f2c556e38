#version 330 core
// A uniform array declared without a size and initialised: the initializer's length is its
// size (naga refused the unsized member of the uniform block), and GL starts it at the
// initializer's values.
in vec2 uv;
out vec4 color;

uniform vec4 palette[] = vec4[](vec4(0.2, 0.4, 0.6, 1.0), vec4(0.8, 0.1, 0.3, 1.0), vec4(0.5, 0.5, 0.0, 1.0));

void main()
{
    int k = int(uv.x * 2.99);
    color = palette[k] * (0.5 + uv.y * 0.5);
}
