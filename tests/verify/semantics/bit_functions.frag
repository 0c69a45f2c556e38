#version 400 core
// bitfieldExtract, bitfieldInsert, bitCount, findLSB, findMSB, bitfieldReverse.
in vec2 uv;
out vec4 color;

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    int v = p.x * 64 + p.y;
    int e = bitfieldExtract(v, 3, 5);
    int ins = bitfieldInsert(v, 5, 2, 3);
    uint rev = bitfieldReverse(uint(v));
    color = vec4(float(e) / 31.0, float(bitCount(v)) / 12.0, float(findLSB(v + 1) + findMSB(v + 1)) / 24.0,
                 float((ins & 255) + int(rev >> 28)) / 270.0);
}
