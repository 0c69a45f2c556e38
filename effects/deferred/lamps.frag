#version 330 core
// Deferred renderer, G-buffer pass 3 (seed 001): unlit emissive lamp markers.
// Normal alpha = 0 marks them unlit, so the combine pass shows their diffuse colour
// as is; they also write a little glow.

in Vertex {
    vec3 colour;
    vec3 worldPos;
} IN;

out vec4 fragColour[4];

void main(void)
{
    fragColour[0] = vec4(IN.colour, 1.0);
    fragColour[1] = vec4(0.5, 1.0, 0.5, 0.0);   // alpha 0: unlit
    fragColour[2] = vec4(IN.colour * 0.35, 1.0);
    fragColour[3] = vec4(IN.worldPos, 1.0);
}
