#version 430
layout(location = 0) in vec3 aPos;
layout(location = 1) in int aMaterial;

flat out int vMaterial;
noperspective out vec2 vScreen;
smooth out float vDepth;

void main()
{
    gl_Position = vec4(aPos, 1.0);
    vMaterial = aMaterial;
    vScreen = aPos.xy;
    vDepth = aPos.z;
}
