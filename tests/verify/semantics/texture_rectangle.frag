#version 330 core
// A rectangle texture (sampler2DRect) is read at texel coordinates, with no level:
// texture, textureProj (the divisor left alone), texelFetch and textureSize.
in vec2 uv;
out vec4 color;

uniform sampler2DRect tex;

void main()
{
    vec2 size = vec2(textureSize(tex));
    vec4 a = texture(tex, uv * size * 0.25 + vec2(3.3, 1.7));
    vec4 b = textureProj(tex, vec3(gl_FragCoord.xy * 2.0, 2.0));
    vec4 c = texelFetch(tex, ivec2(gl_FragCoord.xy) * 3);
    color = vec4(a.r, b.r, c.r, size.x / 128.0);
}
