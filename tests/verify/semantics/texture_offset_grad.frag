#version 330 core
// textureOffset and textureGrad.
in vec2 uv;
out vec4 color;

uniform sampler2D tex;

void main()
{
    vec4 a = textureOffset(tex, uv, ivec2(3, -2));
    vec4 b = textureGrad(tex, uv, vec2(0.02, 0.0), vec2(0.0, 0.05));
    color = mix(a, b, 0.5);
}
