#version 330 core
in vec2 uv;
uniform float iTime;
uniform vec2 iResolution;
out vec4 colour;

float hash(vec2 p) {
    return fract(sin(dot(p, vec2(12.9898, 78.233)) + iTime) * 43758.5453);
}

void main() {
    vec2 pixel = gl_FragCoord.xy / iResolution;
    float shimmer = sin(iTime * 40.0) * 0.5 + 0.5;
    colour = vec4(vec3(hash(pixel) * shimmer) + vec3(uv, 0.0) * 0.1, 1.0);
}
