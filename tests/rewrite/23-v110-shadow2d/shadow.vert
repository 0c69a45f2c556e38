#version 110
attribute vec4 position;

uniform mat4 mvp;
uniform mat4 shadowMatrix;

varying vec4 shadowCoord;

void main()
{
    shadowCoord = shadowMatrix * position;
    gl_Position = mvp * position;
}
