#version 400
in vec2 uv;
out vec4 fragColor;

uniform isampler2D objectIds;
uniform usampler2D materialBits;

void main()
{
    ivec4 id = texture(objectIds, uv);
    uvec4 bits = texture(materialBits, uv);
    fragColor = vec4(float(id.r & 255) / 255.0, float(bits.r & 1u), 0.0, 1.0);
}
