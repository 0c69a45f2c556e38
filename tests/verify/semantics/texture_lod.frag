#version 330 core
// textureLod at fixed levels of the mip chain.
in vec2 uv;
out vec4 color;

uniform sampler2D tex;

void main()
{
    color = mix(textureLod(tex, uv, 0.0), textureLod(tex, uv * 3.0, 2.5), 0.5);
}
