#version 450
#extension GL_EXT_debug_printf : enable
layout(location = 0) in vec3 inPos;
layout(location = 1) in vec2 inUV;
layout(set = 0, binding = 0) uniform Scene { mat4 projection; mat4 view; } scene;
layout(set = 2, binding = 0) uniform Object { mat4 model; uint index; } object;
layout(location = 0) out vec2 outUV;
layout(location = 1) out uint outIndex;
void main()
{
    outUV = inUV;
    outIndex = object.index;
    debugPrintfEXT("vertex %d at %v3f", gl_VertexIndex, inPos);
    gl_Position = scene.projection * scene.view * object.model * vec4(inPos, 1.0);
}
