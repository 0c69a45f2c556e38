#version 330 core
// length, distance, dot, cross, normalize.
in vec2 uv;
out vec4 color;

void main()
{
    vec3 a = vec3(uv * 2.0 - 1.0, 0.5);
    vec3 b = vec3(0.3, -0.6, 0.8);
    vec3 c = cross(a, b);
    color = vec4(length(a) / 2.0, distance(a, b) / 3.0, dot(normalize(a), b) * 0.5 + 0.5, normalize(c).z * 0.5 + 0.5);
}
