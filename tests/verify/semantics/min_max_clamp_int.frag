#version 330 core
// min, max, clamp, abs, sign on ints.
in vec2 uv;
out vec4 color;

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy) - 32;
    color = vec4(float(min(p.x, p.y) + 32) / 64.0, float(max(p.x, p.y) + 32) / 64.0,
                 float(clamp(p.x, -10, 10) + 10) / 20.0, float(abs(p.y) + sign(p.x) + 1) / 34.0);
}
