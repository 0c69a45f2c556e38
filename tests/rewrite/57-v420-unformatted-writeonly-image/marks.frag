#version 420
// GL takes the format of the images bound: only stores, so no format qualifier is needed.
writeonly uniform image2D trail;
layout(binding = 3) writeonly uniform uimage2D hits;
in vec2 uv;
out vec4 colour;

void main()
{
    ivec2 texel = ivec2(gl_FragCoord.xy);
    imageStore(trail, texel, vec4(uv, 0.25, 1.0));
    imageStore(hits, texel, uvec4(1u, uint(texel.x), uint(texel.y), 0u));
    colour = vec4(uv, 0.0, 1.0);
}
