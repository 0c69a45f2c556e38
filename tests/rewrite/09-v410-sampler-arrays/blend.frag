#version 410 core
in vec2 uv;

uniform sampler2D layers[3];
uniform float mixes[3];

out vec4 fragColor;

const int LAST = 2;

vec4 blur(sampler2D tex, vec2 at)
{
    vec2 texel = 1.0 / vec2(textureSize(tex, 0));
    return (texture(tex, at - texel) + texture(tex, at) + texture(tex, at + texel)) / 3.0;
}

void main()
{
    vec4 c = texture(layers[0], uv) * mixes[0];
    c += blur(layers[1], uv) * mixes[1];
    c += texture(layers[LAST], uv) * mixes[2];
    fragColor = c;
}
