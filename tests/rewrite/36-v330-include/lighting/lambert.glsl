#ifndef LAMBERT_GLSL
#define LAMBERT_GLSL
#include "constants.glsl"
float lambert(vec3 n, vec3 l) { return max(dot(normalize(n), normalize(l)), 0.0) * INV_PI * PI; }
#endif
