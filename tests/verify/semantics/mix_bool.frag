#version 330 core
// mix with a boolean selector picks components, no blending.
in vec2 uv;
out vec4 color;

void main()
{
    vec3 a = vec3(uv, 0.25);
    vec3 b = vec3(1.0) - a;
    bvec3 s = bvec3(uv.x > 0.5, uv.y > 0.5, uv.x + uv.y > 1.0);
    color = vec4(mix(a, b, s), 1.0);
}
