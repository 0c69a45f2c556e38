#version 330 core
in float vHeight;

uniform sampler2D heightMap;

out vec4 fragColor;

void main()
{
    float avg = textureLod(heightMap, vec2(0.5), 8.0).r;
    fragColor = vec4(mix(vec3(0.1, 0.4, 0.1), vec3(0.9), clamp(vHeight - avg, 0.0, 1.0)), 1.0);
}
