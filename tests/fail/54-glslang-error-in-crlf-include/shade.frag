#version 110
#include "tone.glsl"
varying vec3 col;
void main()
{
    gl_FragColor = vec4(tone(col), 1.0);
}
