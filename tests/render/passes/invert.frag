#version 330 core
in Vertex { vec2 texCoord; } IN;
uniform sampler2D sceneTex;
out vec4 fragColor;
void main() {
    vec4 c = texture(sceneTex, IN.texCoord);
    fragColor = vec4(1.0 - c.rgb, 1.0);
}
