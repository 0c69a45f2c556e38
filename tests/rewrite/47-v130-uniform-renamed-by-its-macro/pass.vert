#version 130
// An emulator pack's idiom: a uniform, then a macro of the same name that reads it
// (`#define OutputSize vec4(OutputSize, 1.0 / OutputSize)`).
in vec4 VertexCoord;
in vec4 TexCoord;
out vec2 uv;
uniform vec2 OutputSize;
#define OutputSize vec4(OutputSize, OutputSize + 1.0)
void main() {
    gl_Position = VertexCoord;
    uv = TexCoord.xy * OutputSize.zw * 4.0;
}
