#version 330 core
// Finished wood, Marschner et al. 2005 as in seed 004:
//   L_d = k_d I max(n.l, 0)          L_s = k_s I max(n.h, 0)^shininess
//   L_f = k_f I g(beta, psi_h) / cos^2(psi_d / 2)
//   psi_i = asin(l.u / n_cellulose), psi_r = asin(v.u / n_cellulose)  (refraction into the fibre layer)
//   psi_h = psi_r + psi_i, psi_d = psi_r - psi_i, g = gaussian of width beta
//   L = L_d + L_s + L_f when n.l > 0, else 0
// The parameter maps (fibre axis u, beta, k_d, k_f) come from generated textures.

in VertexData
{
    vec3 viewPos;
    vec3 viewNormal;
    vec3 viewTangent;
    float tangentSign;
    vec2 uv;
} fs_in;

out vec4 FragColor;

uniform sampler2D woodPalette;
uniform sampler2D grainNoise;
uniform sampler2D fiberNoise;
uniform mat4 view;
uniform float time;
uniform float ringFrequency;  // growth rings across the board (per uv unit)
uniform float ringDistortion; // how much the noise bends the rings
uniform float fiberTilt;      // max angle (radians) of the fibres out of the surface plane
uniform float curlFrequency;  // tilt reversals along the grain (curly figure)
uniform float betaMin;        // highlight cone width (radians), from the grain map
uniform float betaMax;
uniform float kf;             // fibre highlight strength
uniform float ks;             // surface (finish) specular strength
uniform float shininess;
uniform float lightIntensity;
uniform float lightRadius;    // the light circles the board at this radius ...
uniform float lightHeight;    // ... at this height ...
uniform float lightSpeed;     // ... at this angular speed (radians per second)
uniform float ambient;

const float N_CELLULOSE = 1.55;
const float PI = 3.14159265;
const float TWO_PI = 6.2831853;

vec3 safeNormalize(vec3 v, vec3 fallback)
{
    float len = length(v);
    return len > 1e-6 ? v / len : fallback;
}

void main()
{
    vec2 uv = fs_in.uv;

    // Tangent frame (view space), Gram-Schmidt so t is exactly in the surface plane.
    vec3 n = safeNormalize(fs_in.viewNormal, vec3(0.0, 0.0, 1.0));
    vec3 t = safeNormalize(fs_in.viewTangent - n * dot(n, fs_in.viewTangent), vec3(1.0, 0.0, 0.0));
    vec3 b = cross(n, t) * fs_in.tangentSign;

    // --- parameter maps -------------------------------------------------------------------
    float grain = texture(grainNoise, uv).r;
    // growth rings: stripes along the grain (u), bent by the noise
    float ring = fract((uv.y + (grain - 0.5) * ringDistortion) * ringFrequency);
    float ringShade = smoothstep(0.0, 0.7, ring) * (1.0 - smoothstep(0.85, 1.0, ring));
    vec3 kd = texture(woodPalette, vec2(ringShade, 0.5)).rgb;
    // fibre colour: the same wood, deeper and more saturated
    vec3 kfColour = texture(woodPalette, vec2(0.35 + 0.65 * ringShade, 0.5)).rgb * vec3(1.0, 0.8, 0.55);
    float beta = max(mix(betaMin, betaMax, grain), 0.01); // never zero: divided by below

    // fibre axis u: along the grain, azimuth jittered by the fibre map, tilted out of the
    // surface by an angle that reverses along the grain (curly figure)
    float fib = texture(fiberNoise, vec2(uv.x * 2.0, uv.y * 0.5)).r;
    float azimuth = (fib - 0.5) * 0.4;
    float tilt = fiberTilt * sin(2.0 * PI * curlFrequency * uv.x + fib * 6.0);
    vec3 fiberTS = vec3(cos(tilt) * cos(azimuth), cos(tilt) * sin(azimuth), sin(tilt)); // unit
    vec3 u = safeNormalize(t * fiberTS.x + b * fiberTS.y + n * fiberTS.z, t);

    // --- light and view ------------------------------------------------------------------
    // wrapped to [0, 2pi) before sin/cos (W0717): a phase that grows with time loses f32
    // precision after hours; fract(x / TWO_PI) * TWO_PI is mod(x, TWO_PI)
    float angle = fract(time * lightSpeed / TWO_PI) * TWO_PI;
    vec3 lightWorld = vec3(lightRadius * cos(angle), lightHeight, lightRadius * sin(angle));
    vec3 lightView = (view * vec4(lightWorld, 1.0)).xyz;
    vec3 l = safeNormalize(lightView - fs_in.viewPos, n);
    vec3 v = safeNormalize(-fs_in.viewPos, n);
    vec3 h = safeNormalize(l + v, n);

    float nl = dot(n, l);
    vec3 colour = kd * ambient;
    if (nl > 0.0)
    {
        vec3 Ld = kd * lightIntensity * nl;
        vec3 Ls = vec3(ks * lightIntensity * pow(max(dot(n, h), 0.0), shininess));

        // refraction into the fibre layer: |x.u| <= 1, / 1.55 keeps it inside asin's domain;
        // clamped anyway against rounding
        float psiI = asin(clamp(dot(l, u) / N_CELLULOSE, -1.0, 1.0));
        float psiR = asin(clamp(dot(v, u) / N_CELLULOSE, -1.0, 1.0));
        float psiH = psiR + psiI;
        float psiD = psiR - psiI;
        float g = exp(-psiH * psiH / (2.0 * beta * beta)) / (beta * sqrt(2.0 * PI));
        // |psiD| <= 2 asin(1/1.55) ~ 1.4, so cos(psiD/2) >= 0.76; guarded anyway
        float c = max(cos(psiD * 0.5), 0.05);
        vec3 Lf = kf * kfColour * lightIntensity * g / (c * c);

        colour += Ld + Ls + Lf;
    }

    // soft shoulder so the highlight does not clip to flat white
    colour = colour / (1.0 + 0.25 * colour);
    FragColor = vec4(colour, 1.0);
}
