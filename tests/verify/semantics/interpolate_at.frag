#version 450 core
// interpolateAtOffset, interpolateAtCentroid and interpolateAtSample on a single-sampled
// target (GL evaluates them at the offset, at the centre, at the centre), and
// gl_HelperInvocation (false on every pixel drawn). WebGPU has none of them: effectc
// writes the offset along the varying's derivatives and the others as their value (N0110).
in vec2 uv;
out vec4 color;

void main()
{
    vec2 moved = interpolateAtOffset(uv, vec2(0.5, -0.25));
    vec2 centre = interpolateAtCentroid(uv);
    vec2 sample0 = interpolateAtSample(uv, 0);
    float helper = gl_HelperInvocation ? 1.0 : 0.0;
    color = vec4((moved - centre) * 64.0 + 0.5, sample0.x * 0.5 + helper, uv.y);
}
