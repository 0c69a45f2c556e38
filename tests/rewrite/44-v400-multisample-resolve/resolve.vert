#version 400 core
// A resolve pass that averages the samples of a multisampled colour target by hand. A
// multisampled texture can only be a render target, so drawn bare it reads a placeholder
// (W0404) made as a 4-sample target.
layout(location = 0) in vec2 aPos;
out vec2 uv;

void main()
{
    uv = aPos * 0.5 + 0.5;
    gl_Position = vec4(aPos, 0.0, 1.0);
}
