#version 450
layout(push_constant) uniform Push {
    vec4 SourceSize;
    float Strength;
} params;

layout(location = 0) in vec2 vTexCoord;
layout(location = 0) out vec4 FragColor;
layout(set = 0, binding = 2) uniform sampler2D Source;

// textureGather (GLSL 4.00) is unknown to naga's GLSL front; WGSL has it.
float coverage(vec2 uv)
{
    vec4 taps = textureGather(Source, uv, 1);
    return dot(taps, vec4(0.25));
}

void main()
{
    vec3 color = texture(Source, vTexCoord).rgb;
    float phase = fract(vTexCoord.y * params.SourceSize.y * 0.5);
    float line = phase < 0.5 ? 1.0 : 1.0 - params.Strength;
    FragColor = vec4(color * line * coverage(vTexCoord), 1.0);
}
