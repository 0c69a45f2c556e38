#version 330 core
// A member of an instance-named uniform block named like another global: GLSL reaches it
// only as `params.uv`; naga's GLSL front also declares it as a global, so the bare `uv`
// read the block member (silently, the types agree) until effectc renamed it for naga.
in vec2 uv;
out vec4 color;

uniform Params
{
    vec2 uv;
    float gain;
} params;

void main()
{
    color = vec4(uv * 0.75 + params.uv * params.gain, 0.25, 1.0);
}
