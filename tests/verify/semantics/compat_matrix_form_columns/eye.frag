#version 120
varying vec3 eye;

void main()
{
    gl_FragColor = vec4(fract(abs(eye) * 0.25), 1.0);
}
