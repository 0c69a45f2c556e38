#version 410 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 modelView;
out VertexData {
    vec3 normal;
} vertexOut;
void main() {
    vertexOut.normal = mat3(modelView) * normal;
    gl_Position = modelView * vec4(position, 1.0);
}
