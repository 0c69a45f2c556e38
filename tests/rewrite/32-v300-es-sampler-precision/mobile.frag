#version 300 es
precision mediump float;
precision lowp sampler2D;

in vec2 vUv;

uniform sampler2D uTex;
uniform highp float uTime;

out vec4 fragColor;

void main()
{
    mediump vec4 c = texture(uTex, vUv + vec2(sin(uTime), 0.0) * 0.01);
    fragColor = c;
}
