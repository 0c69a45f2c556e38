#version 420 core
// Sun surface: swirls each vertex around the view axis by an angle that grows with its
// distance from the centre and with time (seed 000, "Shader Coursework").

out vert_out // Outputs read by the fragment stage (block matched by name: vert_out)
{
    vec2 outputTexCoords;
    vec3 swirlPosVector; // Swirled world position
} vs_out;

layout(location = 0) in vec3 vertPosition;
layout(location = 1) in vec2 vertTexCoords;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform float swirlSeed;      // Seed of the per-effect random swirl speed
uniform float swirlIntensity; // Radians of swirl per unit of distance from the centre
uniform float timeVar;        // Time in seconds
uniform float randomConstant; // Scale of the sin-hash in random()

float random(float seed) // A semi-random number in [0, 1) from a seed
{
    return fract(sin(seed) * randomConstant);
}

void main()
{
    vec4 transformPosition = model * vec4(vertPosition, 1.0);

    float angle = length(transformPosition.xy) * swirlIntensity + timeVar * random(swirlSeed);
    mat2 swirlAngleMatrix = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));
    vs_out.swirlPosVector = vec3(swirlAngleMatrix * transformPosition.xy, transformPosition.z);

    gl_Position = projection * view * vec4(vs_out.swirlPosVector, 1.0);
    vs_out.outputTexCoords = vertTexCoords;
}
