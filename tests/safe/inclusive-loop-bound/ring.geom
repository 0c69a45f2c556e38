#version 150
// A loop to an inclusive uniform bound (`i <= sides`): `i++` overflows only at
// sides = INT_MAX, which no program means; an unknown input raises no W0719.
layout(points) in;
layout(line_strip, max_vertices = 64) out;
in vec3 tint[];
out vec3 color;
uniform int sides;
uniform float radius;
void main() {
    color = tint[0];
    for (int i = 0; i <= sides; i++) {
        float angle = 6.2831853 / float(max(sides, 1)) * float(i);
        gl_Position = gl_in[0].gl_Position + vec4(cos(angle) * radius, sin(angle) * radius, 0.0, 0.0);
        EmitVertex();
    }
    EndPrimitive();
}
