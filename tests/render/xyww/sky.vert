#version 330 core
// The skybox trick: z = w puts every vertex on the far plane (depth 1.0), which only the
// depth test GL_LEQUAL lets through against a buffer cleared to 1.0.
in vec3 position;
void main() {
    gl_Position = vec4(position.xy * 2.0, 1.0, 1.0).xyww;
}
