#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in ivec2 aIds;
layout(location = 2) in float aWeight;
layout(location = 3) in uvec4 aMask;
flat out ivec2 vIds;
flat out uvec4 vMask;
out float vWeight;
void main()
{
    vIds = aIds;
    vMask = aMask;
    vWeight = aWeight;
    gl_Position = vec4(aPos.xy * 1.6, 0.0, 1.0);
}
