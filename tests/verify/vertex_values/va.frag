#version 330 core
flat in ivec2 vIds;
flat in uvec4 vMask;
in float vWeight;
out vec4 color;
void main()
{
    color = vec4(float(vIds.x) / 4.0, float(vIds.y & 3) / 3.0, vWeight, float(vMask.w) / 255.0);
}
