#version 330 core
// Nested structs with an array member, constructed and copied.
in vec2 uv;
out vec4 color;

struct Light { vec3 colour; float power[2]; };
struct Scene { Light key; Light fill; };

void main()
{
    Light k = Light(vec3(uv, 0.5), float[2](0.25, 0.75));
    Scene s = Scene(k, k);
    s.fill.colour.x = 1.0 - s.fill.colour.x;
    s.fill.power[1] = uv.y;
    Scene t = s;
    color = vec4(t.key.colour.x, t.fill.colour.x, t.fill.power[1], t.key.power[0]);
}
