#version 130
// A global initialised from uniforms through a macro (the CRT packs' `#define tiltangle
// vec2(tiltangle_x, tiltangle_y) + 0.001`): GL evaluates it before `main`.
uniform float tilt_x, tilt_y;
#define tilt vec2(tilt_x, tilt_y) + 0.25
#define TILT tilt
vec2 sinangle = sin(tilt);
vec2 cosangle = cos(TILT);
in vec4 position;
out vec2 shade;

vec2 tangent(vec2 p) {
    return p * sinangle / cosangle;
}

void main() {
    shade = tangent(vec2(0.5)) + 0.5;
    gl_Position = position;
}
