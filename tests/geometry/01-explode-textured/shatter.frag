#version 420
in Shaded {
    vec2 uv;
    float light;
} shaded;
uniform sampler2D albedo;
layout(location = 0) out vec4 color;
void main() {
    color = vec4(texture(albedo, shaded.uv).rgb * shaded.light, 1.0);
}
