#version 330 core
// Parallax (offset) mapping, fragment stage (seed 002, after Kaneko 2001 / Welsh 2004):
// one height lookup, scaled and biased, shifts the texture coordinate along the
// tangent-space view direction:   h' = h * heightScale + heightBias,  uv' = uv + h' * V.xy.
// This is offset limiting (no division by V.z), so grazing views stay bounded. The seed's
// `texCoord - height * viewVec.yx` swaps the components (a bug): x goes with u, y with v.
// The height map is generated value noise; the normal for the lighting is derived from it
// by finite differences at the shifted coordinate.

in VS_OUT
{
    vec2 TexCoords;
    vec3 TangentViewPos;
    vec3 TangentLightPos;
    vec3 TangentFragPos;
} fs_in;

out vec4 FragColor;

uniform sampler2D diffuseMap;  // checker colour
uniform sampler2D heightMap;   // noise height, 0 = low, 1 = high
uniform float heightScale;     // depth / width of the relief
uniform float heightBias;      // usually -heightScale / 2
uniform float bumpStrength;    // slope scale of the lighting normal
uniform float ambientStrength;

vec3 safeNormalize(vec3 v)
{
    return v * inversesqrt(max(dot(v, v), 1e-12));
}

void main()
{
    vec3 V = safeNormalize(fs_in.TangentViewPos - fs_in.TangentFragPos);

    float h = texture(heightMap, fs_in.TexCoords).r * heightScale + heightBias;
    vec2 uv = fs_in.TexCoords + h * V.xy;

    // Normal from the height map at the shifted coordinate (central differences).
    vec2 texel = 1.0 / vec2(max(textureSize(heightMap, 0), ivec2(1)));
    float hL = texture(heightMap, uv - vec2(texel.x, 0.0)).r;
    float hR = texture(heightMap, uv + vec2(texel.x, 0.0)).r;
    float hD = texture(heightMap, uv - vec2(0.0, texel.y)).r;
    float hU = texture(heightMap, uv + vec2(0.0, texel.y)).r;
    vec3 N = safeNormalize(vec3(-(hR - hL) * 0.5 * bumpStrength, -(hU - hD) * 0.5 * bumpStrength, 1.0));

    vec3 L = safeNormalize(fs_in.TangentLightPos - fs_in.TangentFragPos);
    vec3 albedo = texture(diffuseMap, uv).rgb;
    float diff = max(dot(N, L), 0.0);
    vec3 H = safeNormalize(L + V);
    float spec = diff > 0.0 ? pow(max(dot(N, H), 0.0), 32.0) : 0.0;

    FragColor = vec4(albedo * (ambientStrength + diff) + vec3(0.2) * spec, 1.0);
}
