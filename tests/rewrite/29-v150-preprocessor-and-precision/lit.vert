#version 150
// Engine-style portability header: the branch taken depends on __VERSION__ and GL_ES,
// and an extension macro guards a layout qualifier in the middle of a declaration.
#if (!defined(GL_ES) && __VERSION__ >= 130) || (defined(GL_ES) && __VERSION__ >= 300)
    #define NEW_GLSL
#endif
#ifndef NEW_GLSL
#define in attribute
#define out varying
#endif
#ifdef GL_ARB_explicit_attrib_location
#extension GL_ARB_explicit_attrib_location: require
layout(location = 0)
#endif
in highp vec3 position;
#define EMPTY
#if EMPTY+0 > 1
#error not taken
#endif

uniform mat4 transformation;
out mediump vec2 uv;
flat out int instance;

void main()
{
    uv = position.xy * 0.5 + 0.5;
    instance = gl_InstanceID;
    gl_Position = transformation * vec4(position, 1.0);
}
