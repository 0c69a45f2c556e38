#version 450
layout(set = 0, binding = 1) uniform texture2D colorMap;
layout(set = 1, binding = 0) uniform sampler linearSampler;
layout(set = 0, binding = 2) uniform sampler2D shadowMap;
layout(set = 0, binding = 3) uniform Material { vec4 tint; } material;
layout(location = 0) in vec2 inUV;
layout(location = 1) flat in uint inIndex;
layout(location = 0) out vec4 outColor;
void main()
{
    vec4 c = texture(sampler2D(colorMap, linearSampler), inUV);
    float s = texture(shadowMap, inUV).r;
    outColor = c * material.tint * s;
    if (inIndex == 0xffffffff) {
        discard;
    }
}
