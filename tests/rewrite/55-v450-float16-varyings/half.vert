#version 450
#extension GL_EXT_shader_explicit_arithmetic_types_float16 : require
layout(location = 0) in vec3 inPos;
layout(location = 0) out f16vec3 outColor;
void main()
{
    outColor = f16vec3(inPos * 0.5 + 0.5);
    gl_Position = vec4(inPos, 1.0);
}
