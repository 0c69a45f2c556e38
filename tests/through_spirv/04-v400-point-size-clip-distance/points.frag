#version 400
in vec2 uv;
uniform sampler2D depth;
out vec4 color;
void main()
{
    // textureGather: a construct naga's GLSL front does not take.
    vec4 d = textureGather(depth, uv);
    color = vec4(uv, dot(d, vec4(0.25)), 1.0);
}
