#version 330 core
// Anonymous structs: a uniform of one in both stages (one type of the program, as GL links
// it), a global and a local of one.
in vec4 position;
out vec4 shade;
uniform struct { vec4 tint; vec2 gain; } light;
struct { float k; } scale;
void main()
{
    struct { vec2 p; float q; } corner;
    corner.p = position.xy;
    corner.q = light.gain.y;
    scale.k = 0.5;
    gl_Position = vec4(corner.p, 0.0, 1.0);
    shade = light.tint * corner.q * scale.k + vec4(corner.p * 0.25 + 0.25, 0.0, 0.0);
}
