#version 330 core
// Legal to glslang, refused by Mesa: an #extension directive after a declaration.
in vec2 uv;
out vec4 color;
#extension GL_ARB_shader_bit_encoding : enable

void main()
{
    color = vec4(uv, intBitsToFloat(0x3f800000), 1.0);
}
