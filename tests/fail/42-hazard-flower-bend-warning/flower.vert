#version 330 core
// Seed 004, task 1: the stalk's centre line (height h along +y) is mapped to a circular arc
// of length h, centred at (R, 0) with R = h / phi, phi the bend angle towards the light.
// The seed warns: "When the flower is not bent (the light is directly above it), R becomes
// infinite. You should account for this special case" -- this version does not.

layout(location = 0) in vec2 aTexCoord; // plane_grid uv: u = angle around the stalk, v = height

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform float flowerHeight; // h
uniform float lightX;
uniform float lightZ;
uniform float lightHeight;

out vec3 worldPos;
out vec3 worldNormal;

void main()
{
    float h = flowerHeight;
    float theta = aTexCoord.x * 6.2831853;
    // unbent stalk: a thin cylinder of radius 0.05, height h
    vec3 p = vec3(0.05 * cos(theta), aTexCoord.y * h, 0.05 * sin(theta));
    vec3 n = vec3(cos(theta), 0.0, sin(theta));

    // light-aligned frame: x' points horizontally towards the light
    vec3 lightPos = vec3(lightX, lightHeight, lightZ);
    float horizontal = length(lightPos.xz);
    vec2 dir = vec2(1.0, 0.0);
    if (horizontal > 1e-5)
    {
        dir = lightPos.xz / horizontal;
    }
    // phi: angle between +y and the light, 0 when the light is directly overhead (and the
    // unclamped dot of two unit vectors can round just past 1 there)
    float phi = acos(dot(normalize(lightPos), vec3(0.0, 1.0, 0.0)));

    float R = h / phi;           // infinite when phi = 0
    float a = phi * p.y / h;     // angle along the arc
    float px = dot(p.xz, dir);
    vec3 pf = vec3(R - (R - px) * cos(a), (R - px) * sin(a), dot(p.xz, vec2(-dir.y, dir.x)));
    vec3 nf = vec3(dot(n.xz, dir), n.y, dot(n.xz, vec2(-dir.y, dir.x)));
    nf = vec3(cos(a) * nf.x + sin(a) * nf.y, -sin(a) * nf.x + cos(a) * nf.y, nf.z);

    vec3 bent = vec3(pf.x * dir.x - pf.z * dir.y, pf.y, pf.x * dir.y + pf.z * dir.x);
    vec3 bentNormal = vec3(nf.x * dir.x - nf.z * dir.y, nf.y, nf.x * dir.y + nf.z * dir.x);

    vec4 world = model * vec4(bent, 1.0);
    worldPos = world.xyz;
    worldNormal = mat3(model) * bentNormal;
    gl_Position = projection * view * world;
}
