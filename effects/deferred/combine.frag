#version 330 core
// Deferred renderer, combine pass (seed 001): diffuse * ambient + diffuse * light for
// lit fragments, the plain diffuse colour for unlit ones (is-lit flag from the normal
// buffer's alpha, exactly the seed's formula), then the glow buffer on top, which
// lighting does not touch.

uniform sampler2D diffuseTex;
uniform sampler2D normalTex;
uniform sampler2D lightTex;
uniform sampler2D glowTex;

in Vertex {
    vec2 texCoord;
} IN;

out vec4 fragColour;

void main(void)
{
    vec3 diffuse = texture(diffuseTex, IN.texCoord).xyz;
    vec3 light = texture(lightTex, IN.texCoord).xyz;
    vec3 glow = texture(glowTex, IN.texCoord).xyz;
    float isLit = texture(normalTex, IN.texCoord).a;

    fragColour.xyz = diffuse * 0.1 * isLit + diffuse * (1 - isLit);
    fragColour.xyz += diffuse * light * isLit;
    fragColour.xyz += glow;
    fragColour.a = 1.0;
}
