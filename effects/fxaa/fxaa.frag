#version 330 core
// FXAA post process (seed 001, "FXAA post processing to smooth jagged edges"): an FXAA
// 3.11 quality-preset style pass after Timothy Lottes' algorithm, in the commonly
// published "FXAA 3.11 simplified" GLSL form:
//   1. luma of the centre and its 4 neighbours; skip pixels whose local contrast is below
//      max(edgeThresholdMin, lumaMax * edgeThreshold) (no edge),
//   2. pick the edge direction (horizontal / vertical) from the 3x3 luma gradients and the
//      side of the pixel with the steepest gradient,
//   3. walk along the edge both ways (growing steps) until the luma leaves the edge's
//      average, and shift the sample across the edge by the distance to the nearer end,
//   4. blend in a sub-pixel offset from the 3x3 luma low-pass (scaled by subpixelQuality).
// Every lookup uses explicit LOD 0 (FXAA's FxaaTexTop/FxaaTexOff), so none depends on
// derivatives inside the per-pixel branches.

uniform sampler2D sceneTex;
uniform vec2 screenSize;         // target size in pixels
uniform float edgeThreshold;     // fxaaQualityEdgeThreshold: 0.063 (slow) .. 0.333 (fast)
uniform float edgeThresholdMin;  // fxaaQualityEdgeThresholdMin: 0.0312 .. 0.0833
uniform float subpixelQuality;   // fxaaQualitySubpix: 0 (off) .. 1 (softest)

in Vertex
{
    vec2 texCoord;
} IN;

out vec4 fragColour;

const int SEARCH_STEPS = 12;
// Step lengths along the edge (FXAA_QUALITY__P0..P11 of the 3.11 "39" preset family).
const float SEARCH_STEP[SEARCH_STEPS] = float[SEARCH_STEPS](
    1.0, 1.0, 1.0, 1.0, 1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 4.0, 8.0);

// Perceptual luma (gamma-ish), as in the simplified versions: sqrt of the Rec. 601 weights.
float rgbToLuma(vec3 rgb)
{
    return sqrt(max(dot(rgb, vec3(0.299, 0.587, 0.114)), 0.0));
}

float lumaAt(vec2 uv)
{
    return rgbToLuma(textureLod(sceneTex, uv, 0.0).rgb);
}

void main(void)
{
    vec2 uv = IN.texCoord;
    vec2 texel = 1.0 / max(screenSize, vec2(1.0));

    vec3 colourCentre = textureLod(sceneTex, uv, 0.0).rgb;

    // 1. Local contrast from the centre and its four neighbours.
    float lumaCentre = rgbToLuma(colourCentre);
    float lumaDown  = rgbToLuma(textureLodOffset(sceneTex, uv, 0.0, ivec2( 0, -1)).rgb);
    float lumaUp    = rgbToLuma(textureLodOffset(sceneTex, uv, 0.0, ivec2( 0,  1)).rgb);
    float lumaLeft  = rgbToLuma(textureLodOffset(sceneTex, uv, 0.0, ivec2(-1,  0)).rgb);
    float lumaRight = rgbToLuma(textureLodOffset(sceneTex, uv, 0.0, ivec2( 1,  0)).rgb);

    float lumaMin = min(lumaCentre, min(min(lumaDown, lumaUp), min(lumaLeft, lumaRight)));
    float lumaMax = max(lumaCentre, max(max(lumaDown, lumaUp), max(lumaLeft, lumaRight)));
    float lumaRange = lumaMax - lumaMin;

    if(lumaRange < max(edgeThresholdMin, lumaMax * edgeThreshold))
    {
        fragColour = vec4(colourCentre, 1.0); // no edge here
        return;
    }

    // 2. Edge direction from the 3x3 neighbourhood.
    float lumaDownLeft  = rgbToLuma(textureLodOffset(sceneTex, uv, 0.0, ivec2(-1, -1)).rgb);
    float lumaUpRight   = rgbToLuma(textureLodOffset(sceneTex, uv, 0.0, ivec2( 1,  1)).rgb);
    float lumaUpLeft    = rgbToLuma(textureLodOffset(sceneTex, uv, 0.0, ivec2(-1,  1)).rgb);
    float lumaDownRight = rgbToLuma(textureLodOffset(sceneTex, uv, 0.0, ivec2( 1, -1)).rgb);

    float lumaDownUp = lumaDown + lumaUp;
    float lumaLeftRight = lumaLeft + lumaRight;
    float lumaLeftCorners = lumaDownLeft + lumaUpLeft;
    float lumaDownCorners = lumaDownLeft + lumaDownRight;
    float lumaRightCorners = lumaDownRight + lumaUpRight;
    float lumaUpCorners = lumaUpRight + lumaUpLeft;

    float edgeHorizontal = abs(-2.0 * lumaLeft + lumaLeftCorners)
                         + abs(-2.0 * lumaCentre + lumaDownUp) * 2.0
                         + abs(-2.0 * lumaRight + lumaRightCorners);
    float edgeVertical = abs(-2.0 * lumaUp + lumaUpCorners)
                       + abs(-2.0 * lumaCentre + lumaLeftRight) * 2.0
                       + abs(-2.0 * lumaDown + lumaDownCorners);
    bool isHorizontal = edgeHorizontal >= edgeVertical;

    // The two neighbours across the edge, and which side is steeper.
    float luma1 = isHorizontal ? lumaDown : lumaLeft;
    float luma2 = isHorizontal ? lumaUp : lumaRight;
    float gradient1 = luma1 - lumaCentre;
    float gradient2 = luma2 - lumaCentre;
    bool is1Steepest = abs(gradient1) >= abs(gradient2);
    float gradientScaled = 0.25 * max(abs(gradient1), abs(gradient2));

    float stepLength = isHorizontal ? texel.y : texel.x;
    float lumaLocalAverage = 0.0;
    if(is1Steepest)
    {
        stepLength = -stepLength;
        lumaLocalAverage = 0.5 * (luma1 + lumaCentre);
    }
    else
    {
        lumaLocalAverage = 0.5 * (luma2 + lumaCentre);
    }

    // Start half a pixel across, on the edge itself.
    vec2 currentUV = uv;
    if(isHorizontal)
    {
        currentUV.y += stepLength * 0.5;
    }
    else
    {
        currentUV.x += stepLength * 0.5;
    }

    // 3. Search along the edge in both directions.
    vec2 offset = isHorizontal ? vec2(texel.x, 0.0) : vec2(0.0, texel.y);
    vec2 uv1 = currentUV - offset * SEARCH_STEP[0];
    vec2 uv2 = currentUV + offset * SEARCH_STEP[0];

    float lumaEnd1 = lumaAt(uv1) - lumaLocalAverage;
    float lumaEnd2 = lumaAt(uv2) - lumaLocalAverage;
    bool reached1 = abs(lumaEnd1) >= gradientScaled;
    bool reached2 = abs(lumaEnd2) >= gradientScaled;

    if(!reached1)
    {
        uv1 -= offset * SEARCH_STEP[1];
    }
    if(!reached2)
    {
        uv2 += offset * SEARCH_STEP[1];
    }

    for(int i = 2; i < SEARCH_STEPS; i++)
    {
        if(reached1 && reached2)
        {
            break;
        }
        if(!reached1)
        {
            lumaEnd1 = lumaAt(uv1) - lumaLocalAverage;
        }
        if(!reached2)
        {
            lumaEnd2 = lumaAt(uv2) - lumaLocalAverage;
        }
        reached1 = abs(lumaEnd1) >= gradientScaled;
        reached2 = abs(lumaEnd2) >= gradientScaled;
        if(!reached1)
        {
            uv1 -= offset * SEARCH_STEP[i];
        }
        if(!reached2)
        {
            uv2 += offset * SEARCH_STEP[i];
        }
    }

    // Distances to the two ends; the nearer one decides the offset across the edge.
    float distance1 = isHorizontal ? (uv.x - uv1.x) : (uv.y - uv1.y);
    float distance2 = isHorizontal ? (uv2.x - uv.x) : (uv2.y - uv.y);
    bool isDirection1 = distance1 < distance2;
    float distanceFinal = min(distance1, distance2);
    // Both distances are at least one step (> 0), so the edge length is never zero.
    float edgeLength = max(distance1 + distance2, 1e-6);
    float pixelOffset = -distanceFinal / edgeLength + 0.5;

    // Only move if the luma at the nearer end varies the same way as the centre does.
    bool isLumaCentreSmaller = lumaCentre < lumaLocalAverage;
    bool correctVariation = ((isDirection1 ? lumaEnd1 : lumaEnd2) < 0.0) != isLumaCentreSmaller;
    float finalOffset = correctVariation ? pixelOffset : 0.0;

    // 4. Sub-pixel aliasing: how far the centre is from the 3x3 low-pass luma.
    float lumaAverage = (1.0 / 12.0) * (2.0 * (lumaDownUp + lumaLeftRight)
                                        + lumaLeftCorners + lumaRightCorners);
    // lumaRange > 0 here (it passed the threshold test, and edgeThresholdMin > 0)
    float subPixelOffset1 = clamp(abs(lumaAverage - lumaCentre) / max(lumaRange, 1e-6), 0.0, 1.0);
    float subPixelOffset2 = (-2.0 * subPixelOffset1 + 3.0) * subPixelOffset1 * subPixelOffset1;
    float subPixelOffsetFinal = subPixelOffset2 * subPixelOffset2 * subpixelQuality;
    finalOffset = max(finalOffset, subPixelOffsetFinal);

    vec2 finalUV = uv;
    if(isHorizontal)
    {
        finalUV.y += finalOffset * stepLength;
    }
    else
    {
        finalUV.x += finalOffset * stepLength;
    }

    fragColour = vec4(textureLod(sceneTex, finalUV, 0.0).rgb, 1.0);
}
