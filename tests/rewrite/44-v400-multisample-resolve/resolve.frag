#version 400 core
in vec2 uv;
out vec4 color;

uniform sampler2DMS scene;
uniform int samples;

void main()
{
    ivec2 texel = ivec2(uv * vec2(textureSize(scene)));
    vec4 sum = vec4(0.0);
    for (int i = 0; i < samples; i++) {
        sum += texelFetch(scene, texel, i);
    }
    color = sum / float(max(samples, 1));
}
