#version 120
// Arrays and structs compared whole (GLSL 1.20), which naga's GLSL front does not take.
varying vec2 uv;
uniform float exposure;

struct Tick { vec2 at; float width; };

void main()
{
    float seen[2] = float[2](floor(uv.x * 4.0), floor(uv.y * 4.0));
    float mark[2] = float[2](1.0, 2.0);
    Tick here = Tick(floor(uv * 8.0), 1.0);
    Tick pinned = Tick(vec2(3.0, 3.0), 1.0);
    // The needle: zero length at the gauge's centre, where normalize() is NaN.
    vec2 needle = normalize(uv - 0.5);
    float angle = needle.x * 0.5 + 0.5;
    vec4 c = gl_Color;
    if (seen == mark)
        c.rgb = vec3(1.0) - c.rgb;
    if (here != pinned)
        c.a = angle;
    // Exposure in natural-log stops, ranged down to 0 by the manifest: log(0) is -inf.
    float ev = log(exposure);
    gl_FragColor = vec4(c.rgb * exp(ev), c.a);
}
