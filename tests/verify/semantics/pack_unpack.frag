#version 420 core
// packUnorm2x16/unpackUnorm2x16, packHalf2x16, floatBitsToInt/intBitsToFloat.
in vec2 uv;
out vec4 color;

void main()
{
    uint p = packUnorm2x16(uv);
    vec2 back = unpackUnorm2x16(p);
    vec2 h = unpackHalf2x16(packHalf2x16(uv * 3.0));
    int bits = floatBitsToInt(uv.x + 1.0);
    color = vec4(back.x, h.y / 3.0, float((bits >> 16) & 255) / 255.0, intBitsToFloat(bits) - 1.0);
}
