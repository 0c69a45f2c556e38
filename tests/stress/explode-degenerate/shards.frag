#version 420
in geom_vars { vec2 uv; } frag_in;
layout(location = 0) out vec4 color;
void main() {
    color = vec4(frag_in.uv, 0.5, 1.0);
}
