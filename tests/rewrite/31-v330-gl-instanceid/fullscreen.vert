#version 330 core
uniform vec2 offsets[4];

out vec2 uv;
flat out int instance;

void main()
{
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    uv = p;
    instance = gl_InstanceID;
    gl_Position = vec4(p * 2.0 - 1.0 + offsets[gl_InstanceID & 3], 0.0, 1.0);
}
