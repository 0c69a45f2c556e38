#version 330 core
in vec3 vNormal;
in vec2 vUv;
in vec4 vColor;

layout(location = 0) out vec4 color;
out vec4 normalOut;

void main()
{
    color = vColor * vec4(vUv, 1.0, 1.0);
    normalOut = vec4(normalize(vNormal) * 0.5 + 0.5, 1.0);
}
