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
uniform float randomConstant; // Key mixed into the integer hash in random()

const float TWO_PI = 6.2831853;

// A semi-random number in [0, 1] from a seed. Integer (PCG) hash instead of the old
// fract(sin(seed) * randomConstant) (W0718): GLSL/Vulkan allow sin an error of 2^-11, which
// times 43758 exceeds 0.5, so the sine hash gave a different value on every GPU.
float random(float seed)
{
    uint h = floatBitsToUint(seed) ^ uint(randomConstant);
    h = h * 747796405u + 2891336453u;
    uint w = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
    w = (w >> 22u) ^ w;
    return float(w) / 4294967295.0;
}

void main()
{
    vec4 transformPosition = model * vec4(vertPosition, 1.0);

    // wrapped to [0, 2pi) before sin/cos (W0717): a phase that grows with time loses f32
    // precision after hours; fract(x / TWO_PI) * TWO_PI is mod(x, TWO_PI)
    float angle = fract((length(transformPosition.xy) * swirlIntensity + timeVar * random(swirlSeed)) / TWO_PI) * TWO_PI;
    mat2 swirlAngleMatrix = mat2(cos(angle), sin(angle), -sin(angle), cos(angle));
    vs_out.swirlPosVector = vec3(swirlAngleMatrix * transformPosition.xy, transformPosition.z);

    gl_Position = projection * view * vec4(vs_out.swirlPosVector, 1.0);
    vs_out.outputTexCoords = vertTexCoords;
}
