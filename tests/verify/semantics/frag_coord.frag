#version 330 core
// gl_FragCoord: lower-left origin, pixel centres at .5.
in vec2 uv;
out vec4 color;

void main()
{
    vec2 f = gl_FragCoord.xy;
    color = vec4(f.x / 64.0, f.y / 64.0, fract(f.x), float(f.y < 16.0));
}
