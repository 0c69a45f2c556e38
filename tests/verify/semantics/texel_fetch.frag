#version 330 core
// texelFetch reads the placeholder texture at integer texel coordinates.
in vec2 uv;
out vec4 color;

uniform sampler2D tex;

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    color = texelFetch(tex, p, 0) * 0.5 + texelFetch(tex, p / 2, 1) * 0.5;
}
