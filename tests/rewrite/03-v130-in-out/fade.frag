#version 130
in vec3 vColor;

uniform float fade;

out vec4 outColor;

void main()
{
    outColor = vec4(vColor * fade, 1.0);
}
