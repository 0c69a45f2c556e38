#version 460
// `gl_BaseInstance` (no WGSL built-in) from the shared uniform block, which moves off
// set 0, binding 0 because the camera block holds it.
layout(location = 0) in vec3 vPosition;
layout(location = 0) out vec3 outColor;
layout(set = 0, binding = 0) uniform CameraBuffer {
    mat4 viewproj;
} cameraData;
struct ObjectData {
    vec4 tint;
};
layout(std140, set = 1, binding = 0) readonly buffer ObjectBuffer {
    ObjectData objects[];
} objectBuffer;
void main() {
    outColor = objectBuffer.objects[gl_BaseInstance].tint.rgb + vec3(float(gl_InstanceIndex) * 0.25);
    gl_Position = cameraData.viewproj * vec4(vPosition, 1.0);
}
