#version 330 core
// Sprite-sheet animation (seed 001): the current frame picks its sub-rectangle of a
// horizontal sheet, uv.x = (uv.x + currentFrame) / frameCount. The frame's colour comes
// from the gradient sheet and its flame detail from the noise sheet; the flame outline is a
// procedural mask (alpha), transparent texels are discarded.

in vec2 TexCoord;

out vec4 FragColor;

uniform sampler2D spriteSheet;
uniform sampler2D flameDetail;
uniform float time;
uniform float framesPerSecond;
uniform float frameCount;
uniform float glow;

void main()
{
    float frames = max(floor(frameCount), 1.0);
    float currentFrame = floor(mod(time * framesPerSecond, frames));

    // Sub-rectangle of the current frame in the horizontal sheet.
    vec2 sheetUV = vec2((TexCoord.x + currentFrame) / frames, TexCoord.y);
    vec3 frameColor = texture(spriteSheet, sheetUV).rgb;
    // The detail sheet holds square frames in one row: the same column, 1/frames of the height.
    float detail = texture(flameDetail, vec2(sheetUV.x, TexCoord.y / frames)).r;

    // Flame outline in the frame's local coordinates: x in -1..1, y 0 (base) .. 1 (tip).
    float x = TexCoord.x * 2.0 - 1.0;
    float y = TexCoord.y;
    float sway = (detail - 0.5) * 0.9 * y;                   // each frame bends differently
    float width = 0.95 * sqrt(max(y, 0.0)) * (1.0 - y) * 1.6 + 0.05;
    float d = abs(x - sway) / width;                          // width >= 0.05: never zero
    float body = 1.0 - smoothstep(0.6, 1.0, d);
    body *= smoothstep(0.0, 0.08, y) * (1.0 - smoothstep(0.85, 1.0, y));

    float core = 1.0 - smoothstep(0.0, 0.6, d + y * 0.6);
    vec3 color = frameColor * (0.6 + 0.6 * detail) + vec3(1.0, 0.95, 0.7) * core * glow;
    float alpha = clamp(body * (0.7 + 0.5 * detail), 0.0, 1.0);

    if (alpha < 0.02)
        discard;
    FragColor = vec4(color, alpha);
}
