#version 140
// A depth comparison in a rectangle texture (sampler2DRectShadow): P.xy in texels, P.z the
// reference, compared with the depth placeholder (1.0).
in vec2 uv;
out vec4 color;

uniform sampler2DRectShadow depth;

void main()
{
    float lit = texture(depth, vec3(gl_FragCoord.xy, uv.x * 2.0));
    color = vec4(lit, uv, 1.0);
}
