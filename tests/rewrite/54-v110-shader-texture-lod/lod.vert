#version 110
varying vec4 texcoord;

void main()
{
    gl_Position = gl_Vertex;
    texcoord = vec4(gl_Vertex.xy * 0.5 + 0.5, 0.5, 1.0);
}
