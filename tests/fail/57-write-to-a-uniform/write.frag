#version 330
uniform float level;
out vec4 colour;
void main() {
    float l = --level;
    colour = vec4(l);
}
