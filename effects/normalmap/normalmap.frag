#version 330 core
// Normal mapping, fragment stage (seed 002). There is no normal-map image: the normal is
// derived from a generated height map (value noise) by central finite differences,
//     n_ts = normalize(vec3(-bumpStrength * dH/du, -bumpStrength * dH/dv, 1.0)),
// with dH measured per texel. This is the tangent-space normal a normal map would store
// (as (rgb - 0.5) * 2); TBN takes it to world space, then Phong lighting with a light
// circling the object, so the bumps' lit and shaded sides move from frame to frame.

in VS_OUT
{
    vec3 FragPos;
    vec2 TexCoords;
} fs_in;
in mat3 TBN;

out vec4 FragColor;

uniform sampler2D diffuseMap;
uniform sampler2D heightMap;
uniform vec3 viewPos;
uniform float time;
uniform float bumpStrength;     // height-to-slope scale of the derived normals
uniform vec3 lightColor;
uniform float ambientStrength;
uniform float specularStrength;
uniform float shininess;
uniform float lightRadius;
uniform float lightHeight;
uniform float lightSpeed;

const float TWO_PI = 6.2831853;

vec3 safeNormalize(vec3 v)
{
    return v * inversesqrt(max(dot(v, v), 1e-12));
}

float height(vec2 uv)
{
    return texture(heightMap, uv).r;
}

void main()
{
    vec2 uv = fs_in.TexCoords;

    // Tangent-space normal from the height map by finite differences (one texel each way).
    vec2 texel = 1.0 / vec2(max(textureSize(heightMap, 0), ivec2(1)));
    float hL = height(uv - vec2(texel.x, 0.0));
    float hR = height(uv + vec2(texel.x, 0.0));
    float hD = height(uv - vec2(0.0, texel.y));
    float hU = height(uv + vec2(0.0, texel.y));
    vec3 nTangent = safeNormalize(vec3(-(hR - hL) * 0.5 * bumpStrength,
                                       -(hU - hD) * 0.5 * bumpStrength,
                                       1.0));
    vec3 N = safeNormalize(TBN * nTangent);

    // wrapped to [0, 2pi) before sin/cos (W0717): a phase that grows with time loses f32
    // precision after hours; fract(x / TWO_PI) * TWO_PI is mod(x, TWO_PI)
    float angle = fract(time * lightSpeed / TWO_PI) * TWO_PI;
    vec3 lightPos = vec3(lightRadius * cos(angle), lightHeight, lightRadius * sin(angle));
    vec3 L = safeNormalize(lightPos - fs_in.FragPos);
    vec3 V = safeNormalize(viewPos - fs_in.FragPos);

    vec3 albedo = texture(diffuseMap, uv).rgb;
    vec3 ambient = ambientStrength * albedo;
    float diff = max(dot(N, L), 0.0);
    vec3 diffuse = diff * albedo;
    vec3 R = reflect(-L, N);
    float spec = diff > 0.0 ? pow(max(dot(R, V), 0.0), max(shininess, 1.0)) : 0.0;
    vec3 specular = specularStrength * spec * vec3(1.0);

    FragColor = vec4((ambient + diffuse + specular) * lightColor, 1.0);
}
