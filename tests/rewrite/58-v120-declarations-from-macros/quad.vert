#version 120
// An engine's portability macros write the interface: the storage keyword, type and name
// are all inside the macro's expansion.
#define IN(decl, loc) attribute decl;
#define OUT(decl, loc) varying decl;
#define POSITION 0
#define TEXCOORD0 8

uniform mat4 worldViewProj;
IN(vec4 vertex, POSITION)
IN(vec2 uv0, TEXCOORD0)
OUT(vec2 oUv0, TEXCOORD0)
// A varying named like a later keyword, declared as written: it keeps its qualifier.
centroid varying float sample;

void main()
{
    gl_Position = worldViewProj * vertex;
    oUv0 = uv0;
    sample = uv0.x;
}
