#version 330 core
in vec3 position;
in vec2 texCoord;
out Vertex { vec2 texCoord; } OUT;
void main() {
    OUT.texCoord = texCoord;
    gl_Position = vec4(position.xy, 0.0, 1.0);
}
