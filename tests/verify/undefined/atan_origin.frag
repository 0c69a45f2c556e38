#version 330 core
// Undefined in GLSL: atan(0, 0), reached at the centre of the frame.
in vec2 uv;
out vec4 color;

void main()
{
    vec2 d = floor(gl_FragCoord.xy) - 32.0;
    color = vec4(atan(d.y, d.x) / 6.2831853 + 0.5, uv, 1.0);
}
