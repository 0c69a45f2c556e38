#version 330 core
// WebGPU takes a fragment stage that writes depth only into a pipeline with a depth
// attachment: the render gives it one.
in vec2 uv;
out vec4 colour;

void main()
{
    gl_FragDepth = 0.25 + 0.5 * uv.x;
    colour = vec4(uv, 0.5, 1.0);
}
