#version 330 core
// Deferred renderer, light pass (seed 001): point light with the tutorial's linear
// fall-off, Lambert diffuse and Blinn-Phong specular, computed from the G-buffer normal
// and world position. Unlit fragments (normal alpha 0) get no light; the combine pass
// ignores their light value anyway.

uniform sampler2D normalTex;
uniform sampler2D positionTex;
uniform vec3 cameraPos;
uniform float lightRadius;     // distance at which a light's contribution reaches 0
uniform float lightIntensity;
uniform float specularPower;

in Vertex {
    vec2 texCoord;
} IN;

// Per-light values, the same at every vertex of this instance. (Declared outside the
// block: naga rejects `flat` on block members.)
flat in vec3 vLightPos;
flat in vec3 vLightColour;

out vec4 fragColour;

vec3 safeNormalize(vec3 v)
{
    return v * inversesqrt(max(dot(v, v), 1e-12));
}

void main(void)
{
    vec4 normalSample = texture(normalTex, IN.texCoord);
    float isLit = normalSample.a;
    vec3 N = safeNormalize(normalSample.xyz * 2.0 - 1.0);
    vec3 worldPos = texture(positionTex, IN.texCoord).xyz;

    vec3 toLight = vLightPos - worldPos;
    float dist = length(toLight);
    float atten = 1.0 - clamp(dist / max(lightRadius, 1e-3), 0.0, 1.0);
    atten *= atten;

    vec3 L = safeNormalize(toLight);
    vec3 V = safeNormalize(cameraPos - worldPos);
    vec3 H = safeNormalize(L + V);
    float lambert = max(dot(N, L), 0.0);
    float spec = lambert > 0.0 ? pow(max(dot(N, H), 0.0), max(specularPower, 1.0)) : 0.0;

    vec3 light = vLightColour * lightIntensity * atten * (lambert + 0.4 * spec) * isLit;
    fragColour = vec4(light, 1.0);
}
