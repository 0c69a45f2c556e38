#version 330 core
// Component-wise ivec and uvec arithmetic and conversion.
in vec2 uv;
out vec4 color;

void main()
{
    ivec3 a = ivec3(ivec2(gl_FragCoord.xy), 5);
    ivec3 b = a * 3 - ivec3(7) / 2;
    uvec2 c = uvec2(a.xy) * 2u + 1u;
    vec3 f = vec3(b) / 200.0;
    color = vec4(f.xy, float(c.x + c.y) / 260.0, 1.0);
}
