#version 330 core
// Skybox, vertex stage (seed 000's skybox + environment mapping): a unit cube around the
// camera. The view matrix loses its translation (mat4(mat3(view))) so the cube moves
// with the camera and only turns with it; the cube's own position is the direction that
// looks up the cube map. The pass is drawn first with depth_write = false, so whatever
// comes later is drawn over it: the sky stays behind everything. (The classic
// `gl_Position = pos.xyww` trick needs glDepthFunc(GL_LEQUAL); effectc's depth test is
// `less`, against which depth 1.0 fails on the cleared buffer.)

layout(location = 0) in vec3 position;

uniform mat4 view;
uniform mat4 projection;

out vec3 texDir;

void main()
{
    texDir = position;
    mat4 rotView = mat4(mat3(view));
    gl_Position = projection * rotView * vec4(position, 1.0);
}
