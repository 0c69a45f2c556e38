#version 330 core
// Unsigned multiply and subtract wrap modulo 2^32.
in vec2 uv;
out vec4 color;

void main()
{
    uvec2 p = uvec2(gl_FragCoord.xy);
    uint h = p.x * 2654435761u + p.y * 40503u;
    uint d = p.x - 40u;
    color = vec4(float(h >> 24) / 255.0, float((h >> 8) & 255u) / 255.0, float(d >> 24) / 255.0, 1.0);
}
