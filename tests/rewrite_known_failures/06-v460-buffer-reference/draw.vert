#version 460
#extension GL_EXT_buffer_reference : require
layout(buffer_reference, std430) readonly buffer Positions { vec4 p[]; };
layout(set = 0, binding = 0) uniform Draw { Positions positions; mat4 mvp; } draw;
layout(location = 0) out vec3 outColor;
void main()
{
    vec4 p = draw.positions.p[gl_VertexIndex];
    outColor = p.xyz * 0.5 + 0.5;
    gl_Position = draw.mvp * p;
}
