#version 110
#extension GL_ARB_shader_texture_lod : require
// ARB_shader_texture_lod's explicit-gradient lookups (GLSL 1.10): renamed to textureGrad
// and textureProjGrad; the shadow one reads level 0 (note N0103: WGSL has no depth
// comparison with gradients).
uniform sampler2D colors;
uniform samplerCube sky;
uniform sampler2DShadow depth;
varying vec4 texcoord;

void main()
{
    vec2 dx = dFdx(texcoord.xy) * 4.0;
    vec2 dy = dFdy(texcoord.xy) * 4.0;
    vec4 a = texture2DGradARB(colors, texcoord.xy, dx, dy);
    vec4 b = texture2DProjGradARB(colors, texcoord, dx, dy);
    vec4 c = textureCubeGradARB(sky, vec3(texcoord.xy * 2.0 - 1.0, 1.0), vec3(dx, 0.0), vec3(dy, 0.0));
    vec4 d = shadow2DGradARB(depth, texcoord.xyz, dx, dy);
    gl_FragColor = vec4(a.r, b.g, c.b, 0.5 + 0.5 * d.r);
}
