#version 330 core
// lessThan, equal, greaterThanEqual, any, all, not on vectors.
in vec2 uv;
out vec4 color;

void main()
{
    vec2 a = uv;
    vec2 b = vec2(0.5);
    bvec2 l = lessThan(a, b);
    bvec2 e = equal(ivec2(gl_FragCoord.xy) / 16, ivec2(1, 2));
    color = vec4(float(any(l)), float(all(l)), float(all(not(greaterThanEqual(a, b)))), float(any(e)));
}
