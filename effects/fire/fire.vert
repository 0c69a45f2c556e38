#version 330 core
// Fire (seed 004): the grid's vertices flicker sideways and in depth by a scrolling noise
// sample, more strongly towards the top of the flame.

layout(location = 0) in vec3 aPosition; // plane_grid: xz in -0.5..0.5
layout(location = 1) in vec2 aTexCoord; // v = 0 at the base of the flame, 1 at the top

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform float time;
uniform sampler2D noiseTex;
uniform float displacement; // maximum displacement (object units) at the top
uniform float flickerSpeed; // scroll speed of the displacement noise (v per second)

out vec2 vTexCoord;

const float TWO_PI = 6.2831853;

void main()
{
    vec2 uv = aTexCoord;
    // noise scrolled downwards in v, so its features travel up the flame
    float n1 = texture(noiseTex, uv * 1.5 + vec2(0.0, -time * flickerSpeed)).r;
    float n2 = texture(noiseTex, uv * 0.7 + vec2(0.37, -time * flickerSpeed * 0.6)).r;
    // wrapped to [0, 2pi) before sin/cos (W0717): a phase that grows with time loses f32
    // precision after hours; fract(x / TWO_PI) * TWO_PI is mod(x, TWO_PI)
    float sway = sin(fract(time * 3.1 / TWO_PI) * TWO_PI + uv.y * 4.0) * 0.3;
    float weight = uv.y * uv.y; // the base stays put
    vec3 p = aPosition;
    p.x += ((n1 - 0.5) * 2.0 + sway) * displacement * weight;
    p.y += (n2 - 0.5) * 2.0 * displacement * weight; // local y becomes depth after the model's 90° turn
    vTexCoord = uv;
    gl_Position = projection * view * model * vec4(p, 1.0);
}
