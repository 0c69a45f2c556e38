#version 430
flat in int vMaterial;
noperspective in vec2 vScreen;
smooth in float vDepth;

uniform vec3 palette[4];

out vec4 fragColor;

void main()
{
    vec3 c = palette[vMaterial & 3];
    fragColor = vec4(c * (0.5 + 0.5 * vDepth) + vec3(vScreen, 0.0) * 0.01, 1.0);
}
