#version 330 core
// A flower bud (the uv_sphere) drawn at the tip of a stalk of height h that bends towards
// the light as in seed 004: the centre line becomes an arc of length h with R = h / phi.
// The seed's special case, the light directly overhead (phi = 0, R infinite), keeps the
// stalk unbent instead of dividing by zero. The bud is shaded in its rest pose (vWorldPos,
// vNormal: the mesh through the model matrix) and only drawn displaced to the tip.
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexCoord;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform float flowerHeight; // h
uniform float budRadius;
uniform float lightX;
uniform float lightZ;
uniform float lightHeight;

out vec3 vWorldPos;
out vec3 vNormal;
out vec2 vTexCoord;

void main()
{
    vec3 lightPos = vec3(lightX, lightHeight, lightZ);
    float h = flowerHeight;

    // horizontal direction towards the light (any axis when it is overhead)
    float horizontal = length(lightPos.xz);
    vec2 dir = horizontal > 1e-5 ? lightPos.xz / horizontal : vec2(1.0, 0.0);

    // phi: angle between +y and the light (clamped: a dot of unit vectors can round past 1)
    float phi = acos(clamp(dot(normalize(lightPos), vec3(0.0, 1.0, 0.0)), -1.0, 1.0));

    vec2 tip = vec2(0.0, h); // unbent: the stalk's top
    if (abs(phi) < 1e-4)
    {
        // light overhead: R = h / phi is infinite, keep the stalk unbent
    }
    else
    {
        float R = h / phi;
        tip = vec2(R - R * cos(phi), R * sin(phi));
    }

    vec3 budCentre = vec3(tip.x * dir.x, tip.y, tip.x * dir.y);
    vec4 world = model * vec4(aPos * budRadius, 1.0);
    vWorldPos = world.xyz;
    vNormal = mat3(transpose(inverse(model))) * aNormal;
    vTexCoord = aTexCoord;
    gl_Position = projection * view * (world + vec4(budCentre, 0.0));
}
