#version 110
#extension GL_ARB_texture_rectangle : enable
#define RECT 1
#if RECT
#define texture2D texture2DRect
#define sampler2D sampler2DRect
#endif

uniform sampler2D frame;
varying vec2 coord;

vec4 tap(sampler2D s, vec2 at)
{
    return texture2D(s, at);
}

void main()
{
    vec4 c = texture2D(frame, coord);
    vec4 d = tap(frame, coord + vec2(1.0, 0.0));
    gl_FragColor = vec4(mix(c.rgb, d.gbr, 0.5), 1.0);
}
