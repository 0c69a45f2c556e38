#version 400
in vec2 uv;
out vec4 fragColor;

// Cascades of a shadow map and a set of reflection probes, as many as were bound.
uniform sampler2DArray cascades;
uniform samplerCubeArray probes;

void main()
{
    ivec3 size = textureSize(cascades, 0);
    ivec3 cubes = textureSize(probes, 0);
    // The last cascade, whatever the count.
    float last = float(size.z - 1);
    vec4 depths = textureGather(cascades, vec3(uv, last));
    float layers = float(size.z) / 8.0;
    float probeLayers = float(cubes.z) / 8.0;
    fragColor = vec4(layers, probeLayers, dot(depths, vec4(0.25)) * 0.5, float(size.x + cubes.y) / 8.0);
}
