#version 330 core
// Parallax occlusion mapping, fragment stage (seed 002). The tangent-space view ray is
// marched through the relief in `numLayers` equal depth layers (depth = 1 - height);
// the first layer below the surface stops the march and the hit is refined by linear
// interpolation between the last two layers. Unlike one-step parallax mapping this
// gives occlusion: tile walls hide what is behind them.
//  - The loop has a fixed bound (MAX_LAYERS) and breaks early, as GLSL 330 requires.
//  - Inside the loop the height map is read with textureGrad and gradients taken
//    before the loop: implicit derivatives are undefined in non-uniform control flow.
//  - V.z is clamped away from zero before dividing (grazing views).

in VS_OUT
{
    vec2 TexCoords;
    vec3 TangentViewPos;
    vec3 TangentLightPos;
    vec3 TangentFragPos;
} fs_in;

out vec4 FragColor;

uniform sampler2D diffuseMap;  // checker colour
uniform sampler2D heightMap;   // height, 0 = low, 1 = high
uniform float heightScale;     // relief depth in texture-space units
uniform float numLayers;       // quality knob: depth layers of the march (1..64)
uniform float bumpStrength;    // slope scale of the lighting normal
uniform float ambientStrength;

const int MAX_LAYERS = 64;
const float MIN_VIEW_Z = 0.15; // limits the march length at grazing angles

vec3 safeNormalize(vec3 v)
{
    return v * inversesqrt(max(dot(v, v), 1e-12));
}

float depthAt(vec2 uv, vec2 dx, vec2 dy)
{
    return 1.0 - textureGrad(heightMap, uv, dx, dy).r;
}

vec2 parallaxOcclusion(vec2 texCoords, vec3 V, vec2 dx, vec2 dy)
{
    float layers = clamp(floor(numLayers), 1.0, float(MAX_LAYERS));
    float layerDepth = 1.0 / layers;
    vec2 P = V.xy / max(V.z, MIN_VIEW_Z) * heightScale; // full shift at depth 1
    vec2 deltaUV = P / layers;

    vec2 uv = texCoords;
    float currentLayerDepth = 0.0;
    float currentDepth = depthAt(uv, dx, dy);
    for (int i = 0; i < MAX_LAYERS; ++i)
    {
        if (float(i) >= layers || currentLayerDepth >= currentDepth)
            break;
        uv -= deltaUV;
        currentDepth = depthAt(uv, dx, dy);
        currentLayerDepth += layerDepth;
    }

    // Interpolate between the layer above the surface (prevUV) and the one below it (uv).
    vec2 prevUV = uv + deltaUV;
    float after = currentDepth - currentLayerDepth;                            // <= 0
    float before = depthAt(prevUV, dx, dy) - currentLayerDepth + layerDepth;  // >= 0
    // after - before <= 0 on a hit; min() keeps the divisor nonzero on every path.
    float weight = clamp(after / min(after - before, -1e-5), 0.0, 1.0);
    return mix(uv, prevUV, weight);
}

void main()
{
    vec3 V = safeNormalize(fs_in.TangentViewPos - fs_in.TangentFragPos);
    vec2 dx = dFdx(fs_in.TexCoords);
    vec2 dy = dFdy(fs_in.TexCoords);

    vec2 uv = parallaxOcclusion(fs_in.TexCoords, V, dx, dy);

    // Lighting normal from the height map at the hit (central differences).
    vec2 texel = 1.0 / vec2(max(textureSize(heightMap, 0), ivec2(1)));
    float hL = textureGrad(heightMap, uv - vec2(texel.x, 0.0), dx, dy).r;
    float hR = textureGrad(heightMap, uv + vec2(texel.x, 0.0), dx, dy).r;
    float hD = textureGrad(heightMap, uv - vec2(0.0, texel.y), dx, dy).r;
    float hU = textureGrad(heightMap, uv + vec2(0.0, texel.y), dx, dy).r;
    vec3 N = safeNormalize(vec3(-(hR - hL) * 0.5 * bumpStrength, -(hU - hD) * 0.5 * bumpStrength, 1.0));

    vec3 L = safeNormalize(fs_in.TangentLightPos - fs_in.TangentFragPos);
    vec3 albedo = textureGrad(diffuseMap, uv, dx, dy).rgb;
    float diff = max(dot(N, L), 0.0);
    vec3 H = safeNormalize(L + V);
    float spec = diff > 0.0 ? pow(max(dot(N, H), 0.0), 32.0) : 0.0;

    FragColor = vec4(albedo * (ambientStrength + diff) + vec3(0.2) * spec, 1.0);
}
