#version 120
attribute vec3 aPosition;
attribute vec3 aNormal;

uniform mat4 uModelView;
uniform mat4 uProjection;
uniform mat3 uNormalMatrix;

varying vec3 vNormal;
varying vec3 vEye;

void main()
{
    vec4 eye = uModelView * vec4(aPosition, 1.0);
    vEye = -eye.xyz;
    vNormal = uNormalMatrix * aNormal;
    gl_Position = uProjection * eye;
}
