#version 330 core
// Flower bending towards the light (seed 004, task 1).
//
// The plane_grid is rolled into a flower standing on the origin along +y, height h: a stem
// that opens into a cup of petals. The light, moving with time, is given in the flower's own
// frame. In the vertical plane through the stem and the light ("light-aligned frame", x' the
// horizontal direction towards the light) the stem's centre line is mapped to a circular arc
// of the same length h, tangent to +y at the base, centred at (R, 0) with R = h / phi, where
// phi is the bend angle at the tip. A point at height p_y and offset p_x' from the centre
// line goes to the circle of radius R - p_x' around (R, 0) at angle a = phi * p_y / h:
//     p'_x = R - (R - p_x') cos a,    p'_y = (R - p_x') sin a,   z' unchanged;
// its normal is rotated by the same angle a. When the light is straight above the flower,
// phi = 0 and R is infinite: that case keeps the unbent position (see bendPoint).

layout(location = 0) in vec2 aTexCoord; // plane_grid uv: u = angle around, v = height (0..1)

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform float time;
uniform float flowerHeight; // h
uniform float stemRadius;
uniform float bloomRadius;
uniform float bloomStart;   // fraction of the height where the bloom begins
uniform float petalCount;   // rounded to a whole number so the seam closes
uniform float petalDepth;
uniform float bendAmount;   // bend angle at the tip / angle between +y and the light
uniform float maxBend;      // limit of the bend angle (radians)
uniform float lightSwing;
uniform float lightHeight;
uniform float lightSpeed;

out FlowerData
{
    vec3 worldPos;
    vec3 worldNormal;
    vec3 worldLight;
    float height;  // v: 0 at the base, 1 at the petal tips
    float petal;   // 0 on the stem, rising to 1 at the petal tips
} vs_out;

const float PI = 3.14159265;
const float TWO_PI = 6.2831853;

// The light moves on a figure of eight that passes straight above the flower (at time 0,
// and whenever sin(time * lightSpeed) = 0).
vec3 lightPosition()
{
    // wrapped to [0, 2pi) before sin (W0717): a phase that grows with time loses f32
    // precision after hours. Both phases are wrapped, a and 2a, from the turns elapsed.
    float turns = fract(time * lightSpeed / TWO_PI);
    float a = turns * TWO_PI;
    float a2 = fract(2.0 * turns) * TWO_PI;
    return vec3(lightSwing * sin(a), lightHeight, 0.5 * lightSwing * sin(a2));
}

// Unbent flower surface at angle theta and height fraction t.
vec3 flowerShape(float theta, float t)
{
    float s = clamp((t - bloomStart) / max(1.0 - bloomStart, 1e-3), 0.0, 1.0);
    float open = 1.0 - (1.0 - s) * (1.0 - s);
    float lobes = 1.0 + petalDepth * s * cos(floor(petalCount + 0.5) * theta);
    float r = stemRadius + bloomRadius * open * lobes;
    float y = t * flowerHeight + s * s * bloomRadius * 0.25 * lobes;
    return vec3(r * cos(theta), y, r * sin(theta));
}

// Bend a point and its normal (both in the light-aligned frame: x' towards the light, y up).
void bendPoint(inout vec3 p, inout vec3 n, float phi)
{
    // Light (almost) straight overhead: R = h / phi would be infinite (division by ~0).
    // The bent position tends to the unbent one as phi -> 0, so keep it unchanged.
    if (abs(phi) < 1e-4)
    {
        return;
    }
    float h = max(flowerHeight, 1e-4);
    float R = h / phi;            // phi >= 1e-4 here
    float a = phi * p.y / h;      // angle along the arc
    float c = cos(a);
    float s = sin(a);
    float radius = R - p.x;
    p = vec3(R - radius * c, radius * s, p.z);
    // the neighbourhood of the point is rotated by a (from +y towards +x')
    n = vec3(c * n.x + s * n.y, -s * n.x + c * n.y, n.z);
}

void main()
{
    float theta = aTexCoord.x * 2.0 * PI;
    float t = aTexCoord.y;

    // unbent position and normal (normal from finite differences of the shape)
    vec3 p = flowerShape(theta, t);
    vec3 dTheta = flowerShape(theta + 0.005, t) - flowerShape(theta - 0.005, t);
    vec3 dT = flowerShape(theta, t + 0.002) - flowerShape(theta, t - 0.002);
    vec3 nRaw = cross(dT, dTheta); // outward
    float nLen = length(nRaw);
    vec3 n = nLen > 1e-9 ? nRaw / nLen : vec3(cos(theta), 0.0, sin(theta));

    // light-aligned frame: dir = horizontal direction towards the light
    vec3 light = lightPosition();
    float horizontal = length(light.xz);
    vec2 dir = horizontal > 1e-5 ? light.xz / horizontal : vec2(1.0, 0.0); // any axis when overhead
    vec2 side = vec2(-dir.y, dir.x);
    // angle between +y and the light seen from the base (0 when overhead; atan(0, 0) avoided)
    float lightAngle = horizontal > 1e-5 ? atan(horizontal, light.y) : 0.0;
    float phi = clamp(bendAmount * lightAngle, 0.0, maxBend);

    vec3 pf = vec3(dot(p.xz, dir), p.y, dot(p.xz, side));
    vec3 nf = vec3(dot(n.xz, dir), n.y, dot(n.xz, side));
    bendPoint(pf, nf, phi);
    vec3 bent = vec3(pf.x * dir.x + pf.z * side.x, pf.y, pf.x * dir.y + pf.z * side.y);
    vec3 bentNormal = vec3(nf.x * dir.x + nf.z * side.x, nf.y, nf.x * dir.y + nf.z * side.y);

    vec4 world = model * vec4(bent, 1.0);
    vs_out.worldPos = world.xyz;
    vs_out.worldNormal = mat3(model) * bentNormal; // model: translation only
    vs_out.worldLight = (model * vec4(light, 1.0)).xyz;
    vs_out.height = t;
    vs_out.petal = clamp((t - bloomStart) / max(1.0 - bloomStart, 1e-3), 0.0, 1.0);
    gl_Position = projection * view * world;
}
