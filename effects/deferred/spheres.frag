#version 330 core
// Deferred renderer, G-buffer pass 2 (seed 001): lit spheres, fragment stage.
// Diffuse colour, normal with is-lit = 1, no glow, world position.

in Vertex {
    vec3 colour;
    vec3 normal;
    vec3 worldPos;
} IN;

out vec4 fragColour[4];

// normalize() that cannot divide by zero: a mesh with zero normals (degenerate faces;
// `effectc stress`'s geometry cases) gives N = 0 here, not NaN.
vec3 safeNormalize(vec3 v)
{
    return v * inversesqrt(max(dot(v, v), 1e-12));
}

void main(void)
{
    vec3 N = safeNormalize(IN.normal);
    fragColour[0] = vec4(IN.colour, 1.0);
    fragColour[1] = vec4(N * 0.5 + 0.5, 1.0);   // alpha 1: lit
    fragColour[2] = vec4(0.0, 0.0, 0.0, 1.0);   // no glow
    fragColour[3] = vec4(IN.worldPos, 1.0);
}
