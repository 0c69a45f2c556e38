#version 330 core
// reflect, refract (with total internal reflection), faceforward.
in vec2 uv;
out vec4 color;

void main()
{
    vec3 i = normalize(vec3(uv * 2.0 - 1.0, -1.0));
    vec3 n = normalize(vec3(0.2, 0.3, 1.0));
    vec3 r = reflect(i, n);
    vec3 t = refract(i, n, 1.0 / (1.0 + uv.y));
    vec3 f = faceforward(n, i, vec3(uv.x - 0.5, 0.0, 1.0));
    color = vec4(r.x * 0.5 + 0.5, t.y * 0.5 + 0.5, length(t), f.z * 0.5 + 0.5);
}
