#version 150
#if __VERSION__ < 130
#define texture texture2D
#else
#define texture2D texture
#endif
in mediump vec2 uv;
flat in int instance;
out vec4 color;
uniform sampler2D albedo;
#define ALBEDO texture2D(albedo, uv).rgb

float luminance(highp vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }
vec4 tap(sampler2D s, mediump vec2 at) { return texture2D(s, at); }

void main()
{
    int mask = 0xFFFFFFFF;
    float l = luminance(ALBEDO);
    color = tap(albedo, uv) * l + vec4(float(instance) * float(mask & 1));
}
