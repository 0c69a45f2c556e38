#version 400
in vec2 uv;
out vec4 fragColor;

uniform sampler2D depth;

void main()
{
    vec4 d = textureGather(depth, uv);
    fragColor = vec4(vec3(dot(d, vec4(0.25))), 1.0);
}
