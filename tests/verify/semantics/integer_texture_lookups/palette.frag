#version 330 core
// `texture` and `textureLod` of integer samplers: GL reads the nearest texel (integer
// textures are never filtered), wrapping as GL_REPEAT outside [0, 1]; an array's layer is
// the rounded coordinate, clamped to the layers. Also through a sampler parameter.
uniform usampler2D indices;
uniform isampler2DArray layers;
in vec2 uv;
out vec4 colour;

uint fetchIndex(usampler2D s, vec2 p)
{
    return texture(s, p).r;
}

void main()
{
    vec2 p = uv * 2.6 - 0.8;
    uvec4 a = texture(indices, p);
    ivec4 b = textureLod(layers, vec3(p.yx, uv.x * 3.0 - 0.5), 0.0);
    uint c = fetchIndex(indices, p + vec2(0.37, 0.0));
    colour = vec4(vec3(a.rgb % 256u) / 255.0, 1.0) * 0.5 + vec4(vec3(abs(b.rgb) % 256) / 255.0, 1.0) * 0.25 + float(c % 7u) / 28.0;
}
