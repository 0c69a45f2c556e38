#version 330 core
// Soft round particle (seed 001): alpha falls off with the distance from the quad centre,
// with a brighter rim and highlight so each particle reads as a bubble.

in vec2 TexCoord;
in float Fade;

out vec4 FragColor;

uniform vec3 particleColor;
uniform float brightness;

void main()
{
    vec2 p = TexCoord * 2.0 - 1.0;         // -1..1 across the quad
    float d = length(p);                   // 0 at the centre, 1 at the edge midpoints
    if (d > 1.0)
        discard;

    float soft = 1.0 - smoothstep(0.0, 1.0, d);
    float rim = smoothstep(0.6, 0.85, d) * (1.0 - smoothstep(0.85, 1.0, d));
    float highlight = 1.0 - smoothstep(0.0, 0.25, length(p - vec2(-0.35, 0.35)));

    vec3 color = particleColor * brightness + vec3(1.0) * highlight * 0.6;
    float alpha = clamp((soft * soft * 0.6 + rim * 0.8 + highlight * 0.5) * Fade, 0.0, 1.0);
    FragColor = vec4(color, alpha);
}
