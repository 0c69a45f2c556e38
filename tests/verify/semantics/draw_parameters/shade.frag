#version 460
in vec4 params;
out vec4 frag;
void main() {
    frag = params;
}
