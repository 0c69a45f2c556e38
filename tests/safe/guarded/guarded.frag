#version 330 core
// The seed hazards, each written with its guard.
in vec3 vWorldPos;
in vec3 vNormal;
in vec2 vTexCoord;

out vec4 FragColor;

uniform sampler2D sceneTex;
uniform vec4 camera_position; // vec4: see the report (a vec3 gets no facts)
uniform float timeVarFrag;
uniform float lightX;
uniform float lightZ;
uniform float lightHeight;
uniform vec3 fiberDir;
uniform float minBI;
uniform float maxBI;
uniform float bFrequency;
uniform int bloomRange;
uniform float bloomIntensity;
uniform float shininess;
uniform float exposure;
uniform float sinT2Scale;
uniform float lightFalloff;

const float N_CELLULOSE = 1.55;

void main()
{
    vec3 lightPos = vec3(lightX, lightHeight, lightZ); // always above the bud
    // mesh normals through the normal matrix, renormalized per pixel
    vec3 N = normalize(vNormal);
    // the light stays outside the mesh: never a zero vector
    vec3 L = normalize(lightPos - vWorldPos);
    vec3 V = normalize(camera_position.xyz - vWorldPos);
    vec3 R = reflect(-L, N);

    // Phong with the base clamped (shininess > 0)
    float diffuse = max(dot(N, L), 0.0);
    float specular = pow(max(dot(R, V), 0.0), shininess);

    // Blinn half vector: L + V is zero when they are opposite, so divide by a floored length
    vec3 halfSum = L + V;
    vec3 H = halfSum / max(length(halfSum), 1e-6);
    float blinn = pow(max(dot(N, H), 0.0), shininess);

    // radial direction around the bud's axis, zero at the poles: floored length
    vec2 radial = vWorldPos.xz / max(length(vWorldPos.xz), 1e-6);

    // seed 004 wood: refraction into the fibre layer, |dot of unit vectors| / 1.55 < 1;
    // the fibres run around the bud
    vec3 u = normalize(fiberDir + vec3(-radial.y, 0.0, radial.x));
    float psi_i = asin(dot(normalize(L), normalize(u)) / N_CELLULOSE);
    float psi_r = asin(dot(normalize(V), normalize(u)) / N_CELLULOSE);
    float fibre = cos(0.5 * (psi_r - psi_i));

    // the light's heading in the xz plane is zero when the light is overhead: its length,
    // kept in a variable, is tested before normalize
    vec2 lightXZ = vec2(lightX, lightZ);
    vec2 heading = vec2(0.0, 1.0);
    float headingLen = length(lightXZ);
    if (headingLen > 1e-4) {
        heading = normalize(lightXZ);
    }
    fibre *= 0.75 + 0.25 * heading.x;

    // seed 000 bloom pulse, with the phase wrapped before sin
    float currentBI = mix(minBI, maxBI, 0.5 + 0.5 * sin(mod(timeVarFrag * bFrequency, 6.2831853)));

    // seed 003 bloom curve: bloomRange = 1 no longer divides by zero
    vec4 bloom = vec4(0.0);
    vec2 delta = vec2(1.0 / 64.0, 0.0);
    float z = 0.0;
    int ranger = bloomRange;
    // the shipped bloom's form: an integer guard, ranger > 1 means ranger - 1 >= 1
    float curveStep = 0.0;
    if (ranger > 1) {
        curveStep = 16.0 / float(ranger - 1);
    }
    float startCurve = 8.0;
    for (int i = 0; i < ranger; i++)
    {
        vec2 offset = delta * (z - float((ranger - 1) / 2));
        vec4 tmp = texture(sceneTex, vTexCoord + offset);
        float curve = 1.0 / (pow(2.0, abs(-startCurve + (startCurve * 2.0) / float(max(ranger - 1, 1)) * z)));
        bloom += tmp * curve * bloomIntensity * (1.0 + 0.01 * curveStep);
        z += 1.0;
    }

    // transmitted cosine, total internal reflection clamped to 0
    float x = sinT2Scale;
    float cosT = sqrt(max(1.0 - x, 0.0));

    // light falloff and exposure, floored away from 0
    vec3 toLight = lightPos - vWorldPos;
    float dist2 = dot(toLight, toLight);
    float attenuation = inversesqrt(max(lightFalloff * dist2, 1e-12));
    float ev = log(max(exposure, 1e-6));

    vec3 colour = vec3(0.8, 0.3, 0.2) * diffuse * cosT * (0.5 + 0.5 * fibre)
                + vec3(specular + blinn) + bloom.rgb * currentBI;
    FragColor = vec4(colour * min(attenuation, 1.0) * exp(ev), 1.0);
}
