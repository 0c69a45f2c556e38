#version 130
in vec2 uv;
out vec4 color;
uniform vec2 OutputSize;
uniform vec2 TextureSize;
#define OutputSize vec4(OutputSize, OutputSize + 1.0)
#define SourceSize vec4(TextureSize, 1.0 / TextureSize)
void main() {
    vec2 cell = fract(uv * OutputSize.zw);
    color = vec4(cell, OutputSize.z * 0.5, SourceSize.x > 0.0 ? 1.0 : 0.5);
}
