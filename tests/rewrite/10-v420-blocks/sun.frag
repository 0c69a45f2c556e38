#version 420 core
in SurfaceData {
    vec2 texCoords;
    vec3 worldPos;
} frag_in;

layout(binding = 0) uniform sampler2D surface;

out vec4 fragColor;

void main()
{
    vec3 c = texture(surface, frag_in.texCoords).rgb;
    fragColor = vec4(c * (1.0 + 0.1 * sin(frag_in.worldPos.y)), 1.0);
}
