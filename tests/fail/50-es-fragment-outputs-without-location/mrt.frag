#version 300 es
precision mediump float;
out vec4 albedo;
layout(location = 1) out vec4 normal;
void main()
{
    albedo = vec4(1.0);
    normal = vec4(0.0, 0.0, 1.0, 0.0);
}
