#version 330 core
in Vertex { vec2 texCoord; } IN;
uniform isampler2D sceneTex;
out vec4 fragColor;
void main() {
    fragColor = vec4(texelFetch(sceneTex, ivec2(gl_FragCoord.xy), 0)) / 255.0;
}
