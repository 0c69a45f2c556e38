#version 100
precision mediump float;

uniform sampler2D layers[3];
varying vec2 uv;

// The array is passed whole, as WebGL code does to share one blend among programs.
vec4 blend(sampler2D ts[3], vec2 p);

void main()
{
    gl_FragColor = blend(layers, uv);
}

vec4 blend(sampler2D ts[3], vec2 p)
{
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 3; i++) {
        sum += texture2D(ts[i], p) / 3.0;
    }
    return sum + texture2D(ts[1], p.yx) * 0.1;
}
