#version 300 es
precision highp float;

// Loose uniforms, a function reading one before the struct the uniform block needs, and
// that struct's member named like a loose uniform (`color`): the struct moves up ahead of
// the block, since its member names no global.
uniform mat4 viewMatrix;

float half_of(float x) { return 0.5 * x; }

uniform vec3 color;

vec3 to_view(vec3 n)
{
    return (viewMatrix * vec4(n, 0.0)).xyz;
}

struct Light {
    vec3 direction;
    vec3 color;
};
uniform Light lights[1];

in vec3 normal;
out vec4 fragColor;

void main()
{
    float lit = max(dot(to_view(normal), lights[0].direction), 0.0);
    fragColor = vec4(color * half_of(1.0) + lights[0].color * lit, 1.0);
}
