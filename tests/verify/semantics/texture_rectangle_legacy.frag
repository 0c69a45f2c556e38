#version 120
#extension GL_ARB_texture_rectangle : require
// GLSL 1.20 with ARB_texture_rectangle: texture2DRect and texture2DRectProj (vec4: the
// divisor is w) at texel coordinates, past the edge too (clamped, as GL requires).
varying vec2 uv;
uniform sampler2DRect tex;

void main()
{
    vec4 a = texture2DRect(tex, uv * 600.0 - 20.0);
    vec4 b = texture2DRectProj(tex, vec4(gl_FragCoord.xy * 1.5, 7.0, 0.5));
    gl_FragColor = a * 0.5 + b * 0.5;
}
