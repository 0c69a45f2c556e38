#version 330 core
// A 2D array texture (the placeholder in every layer) sampled with its mip chain.
in vec2 uv;
out vec4 color;
uniform sampler2DArray layers;

void main()
{
    color = texture(layers, vec3(uv * 3.0, 0.0)) * 0.5 + textureLod(layers, vec3(uv, 1.0), 2.0) * 0.5;
}
