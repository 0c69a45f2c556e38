#version 130
in float shared;

uniform vec3 sample;

void main()
{
    vec3 buffer = sample * shared;
    gl_FragColor = vec4(buffer, 1.0);
}
