#version 120
// Uniform initializers of a struct and an array of structs (GLSL 1.20): GL starts the
// uniforms there, member by member. No vertex stage: GL's fixed-function one draws.
struct Band { float lo; vec3 tint; };
struct Mix { int n; vec2 w; };
uniform Band bands[2] = Band[2](Band(0.25, vec3(1.0, 0.5, 0.0)), Band(0.75, vec3(0.0, 0.5, 1.0)));
uniform Mix mixing = Mix(2, vec2(0.25, 0.75));

void main()
{
    float x = gl_FragCoord.x / 64.0;
    vec3 c = x < bands[0].lo ? bands[0].tint : (x < bands[1].lo ? bands[1].tint : vec3(float(mixing.n) * 0.25));
    gl_FragColor = vec4(c * mixing.w.y + mixing.w.x * 0.25, 1.0);
}
