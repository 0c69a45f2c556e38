#version 330 core
// Undefined in GLSL: `%` with a negative operand. OpenGL drivers and WebGPU legitimately
// give different results (Mesa and WGSL disagree on half of this frame).
in vec2 uv;
out vec4 color;

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    int r = (p.x - 32) % 7;
    color = vec4(float(r + 7) / 14.0, uv, 1.0);
}
