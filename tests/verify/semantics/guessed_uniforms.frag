#version 330 core
// Uniforms with no value: both drivers get effectc's guesses (time, resolution, identity).
in vec2 uv;
out vec4 color;

uniform float time;
uniform vec2 resolution;
uniform mat4 model;
uniform int count;

void main()
{
    vec4 p = model * vec4(uv, 0.0, 1.0);
    color = vec4(p.xy * (1.0 + time), gl_FragCoord.x / resolution.x, float(count) * 0.1 + 0.5);
}
