#version 330 core
// Pixelize post process (seed 003, "Pixelize Post Processing"): snaps the texture
// coordinate to blocks of pixelSize x pixelSize screen pixels (no change for sizes of 1 or
// less) and tints the result by colourCorrection.

uniform sampler2D sceneTex;
uniform float pixelSize;       // block size in screen pixels
uniform vec2 screenSize;       // target size in pixels
uniform vec4 colourCorrection; // per-channel multiplier

in Vertex
{
    vec2 texCoord;
} IN;

out vec4 fragColor;

void main(void)
{
    vec2 newUV = floor(IN.texCoord.xy * screenSize / pixelSize)
                 / screenSize * pixelSize;
    if(floor(pixelSize)<=1)
    {
        newUV = IN.texCoord.xy;
    }
    vec4 tmp = texture2D(sceneTex, newUV);

    fragColor = tmp;
    fragColor = fragColor * colourCorrection;
}
