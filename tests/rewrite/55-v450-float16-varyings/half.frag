#version 450
#extension GL_EXT_shader_explicit_arithmetic_types_float16 : require
layout(location = 0) in f16vec3 inColor;
layout(location = 0) out vec4 outColor;
void main() { outColor = vec4(vec3(inColor), 1.0); }
