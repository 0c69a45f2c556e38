#version 120
#define IN(decl, loc) varying decl;
#define TEXCOORD0 8

uniform sampler2D source;
IN(vec2 oUv0, TEXCOORD0)
centroid varying float sample;

void main()
{
    gl_FragColor = texture2D(source, oUv0) * vec4(oUv0, sample, 1.0);
}
