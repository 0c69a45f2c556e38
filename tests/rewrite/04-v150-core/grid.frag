#version 150 core
in vec3 worldPos;

uniform float spacing;
uniform vec3 lineColor;

out vec4 fragColor;

void main()
{
    vec2 cell = abs(fract(worldPos.xz / spacing - 0.5) - 0.5) / fwidth(worldPos.xz / spacing);
    float line = 1.0 - min(min(cell.x, cell.y), 1.0);
    fragColor = vec4(lineColor, line);
}
