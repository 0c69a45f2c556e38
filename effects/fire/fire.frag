#version 330 core
// Fire (seed 004): three samples of one noise texture, each with its own uv scale and its own
// v scroll speed (v per second), are averaged; the average, shaped so the flame narrows and
// dies out upwards, indexes the fire palette.

in vec2 vTexCoord;

out vec4 FragColor;

uniform sampler2D noiseTex;
uniform sampler2D firePalette;
uniform float time;
uniform float textureScale1;
uniform float textureScale2;
uniform float textureScale3;
uniform float scrollSpeed1;
uniform float scrollSpeed2;
uniform float scrollSpeed3;
uniform float noiseContrast; // spreads the averaged noise (three averaged samples cluster at 0.5)
uniform float flameTaper;    // how fast the flame narrows and fades with height

void main()
{
    vec2 uv = vTexCoord;

    // Three texture coordinates: scaled, then scrolled in v with time. The texture's wrap
    // mode is repeat, so coordinates beyond 1 wrap around.
    vec2 uv1 = uv * textureScale1 + vec2(0.0, -time * scrollSpeed1);
    vec2 uv2 = uv * textureScale2 + vec2(0.0, -time * scrollSpeed2);
    vec2 uv3 = uv * textureScale3 + vec2(0.0, -time * scrollSpeed3);
    float n = (texture(noiseTex, uv1).r + texture(noiseTex, uv2).r + texture(noiseTex, uv3).r) / 3.0;
    n = clamp((n - 0.5) * noiseContrast + 0.5, 0.0, 1.0);

    // Flame shape: widest at the base, narrowing upwards; noise eats into the edges.
    float height = clamp(uv.y, 0.0, 1.0);
    float halfWidth = 0.45 * (1.0 - pow(height, 1.0 / max(flameTaper, 0.05))) + 0.01;
    float across = abs(uv.x - 0.5);
    float body = 1.0 - smoothstep(0.0, halfWidth, across - (n - 0.5) * halfWidth); // halfWidth >= 0.01
    float fade = (1.0 - height * 0.8) * smoothstep(0.0, 0.1, height); // soft base, dying tip
    float index = clamp(body * fade * (0.2 + 1.1 * n), 0.0, 1.0);

    // Palette lookup; low indices fade to black (smoke-free edges), the hottest go to white.
    vec3 colour = texture(firePalette, vec2(index, 0.5)).rgb;
    colour *= smoothstep(0.05, 0.35, index);
    colour = mix(colour, vec3(1.0, 0.97, 0.85), smoothstep(0.82, 1.0, index));

    FragColor = vec4(colour, 1.0);
}
