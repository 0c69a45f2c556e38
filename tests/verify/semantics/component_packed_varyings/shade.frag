#version 440
layout(location = 0) in vec3 colour;
layout(location = 0, component = 3) in float opacity;
layout(location = 3, component = 1) in float extra;
out vec4 frag;
void main() {
    frag = vec4(colour.r, colour.g * opacity, colour.b + extra, opacity);
}
