#version 120
// GLSL 1.20: texture2D, gl_FragColor and varying (the vertex stage writes `uv` as an `out`).
varying vec2 uv;
uniform sampler2D tex;

void main()
{
    gl_FragColor = texture2D(tex, uv * 2.0) * vec4(uv, 1.0, 1.0);
}
