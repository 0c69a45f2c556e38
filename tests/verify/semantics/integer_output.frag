#version 330 core
// An integer colour output: the frame is an integer target on both sides, and each channel
// shows its value clamped to 0..255 (negative and large values included), opaque.
in vec2 uv;
out ivec4 color;

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    color = ivec4(p.x * 5 - 40, p.y * 4, 300 - p.x * 6 - p.y, -7);
}
