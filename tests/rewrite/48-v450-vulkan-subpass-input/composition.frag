#version 450
// Input attachments (WebGPU has none): each reads the attachment's texel under the
// fragment, as a texture of the same binding does.
layout(input_attachment_index = 0, set = 0, binding = 0) uniform subpassInput inputAlbedo;
layout(input_attachment_index = 1, binding = 1) uniform usubpassInput inputMaterial;
layout(set = 0, binding = 2) uniform Light { vec4 color; } light;
layout(location = 0) in vec2 inUV;
layout(location = 0) out vec4 outColor;

vec3 albedo() { return subpassLoad(inputAlbedo).rgb; }

void main()
{
    uint material = subpassLoad( inputMaterial ).r;
    outColor = vec4(albedo() * light.color.rgb * (material == 0u ? 1.0 : 0.5), 1.0);
}
