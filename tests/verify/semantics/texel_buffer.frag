#version 330 core
// Buffer textures (samplerBuffer, isamplerBuffer): WebGPU has none, so effectc reads a
// read-only storage buffer of texels (N0107), which render fills with zeros, as GL reads a
// buffer texture with no buffer bound. (textureSize differs: GL's unbound buffer has none.)
in vec2 uv;
out vec4 color;

uniform samplerBuffer table;
uniform isamplerBuffer ids;

void main()
{
    int n = textureSize(table);
    vec4 t = texelFetch(table, int(uv.x * 16.0));
    ivec4 i = texelFetch(ids, 3);
    color = vec4(uv, t.x + float(i.y) + float(min(n, 0)), 1.0 - t.w);
}
