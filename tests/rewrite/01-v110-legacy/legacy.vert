#version 110
attribute vec3 position;
attribute vec2 texcoord;

uniform mat4 modelViewProjection;

varying vec2 vUv;

void main()
{
    vUv = texcoord;
    gl_Position = modelViewProjection * vec4(position, 1.0);
}
