#version 330 core
in Vertex { vec2 texCoord; } IN;
uniform sampler2D sceneTex;
out vec4 fragColor;
void main() {
    fragColor = vec4(1.0) - texture(sceneTex, IN.texCoord);
}
