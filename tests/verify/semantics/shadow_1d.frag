#version 110
// A 1D depth comparison (sampler1DShadow): shadow1D's P = (s, unused, ref) and
// shadow1DProj's (s, unused, ref, q), compared with the depth placeholder (1.0).
varying vec2 uv;
uniform sampler1DShadow depth;

void main()
{
    float a = shadow1D(depth, vec3(uv.x, 7.0, uv.y * 2.0)).r;
    float q = 0.5 + uv.x;
    float b = shadow1DProj(depth, vec4(uv.y * q, 3.0, uv.x * 2.0 * q, q)).r;
    gl_FragColor = vec4(a, b, uv.x, 1.0);
}
