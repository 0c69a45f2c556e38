#version 430 core
// Each corner is coloured from the next corner's varyings (a corner index known only at
// run time): its last tint (an element index known only at run time) times its last
// weight. The triangle's colours turn by one corner.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in Shades {
    vec3 tint[4];
} shades[];
in float weight[][2];
out vec3 color;
void main() {
    int last = 3 - gl_PrimitiveIDIn % 2;
    for (int i = 0; i < 3; i++) {
        int next = (i + 1 + gl_PrimitiveIDIn) % 3;
        gl_Position = gl_in[i].gl_Position;
        color = shades[next].tint[last] * weight[next][last - 2];
        EmitVertex();
    }
    EndPrimitive();
}
