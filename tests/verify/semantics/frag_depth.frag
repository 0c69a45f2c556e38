#version 330 core
// gl_FragDepth written: what the depth test keeps, the frame still shows.
in vec2 uv;
out vec4 color;

void main()
{
    gl_FragDepth = uv.x;
    color = vec4(uv, gl_FragCoord.z, 1.0);
}
