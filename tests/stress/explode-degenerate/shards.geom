#version 420
// Every triangle flies out along its face normal, unguarded: a zero-area triangle has no
// normal, and normalize(0) is NaN.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vert_vars { vec2 uv; } geom_in[];
out geom_vars { vec2 uv; } geom_out;
uniform float spread;
vec3 faceNormal() {
    vec3 a = gl_in[0].gl_Position.xyz - gl_in[1].gl_Position.xyz;
    vec3 b = gl_in[2].gl_Position.xyz - gl_in[1].gl_Position.xyz;
    return normalize(cross(a, b));
}
void main() {
    vec3 n = faceNormal();
    for (int i = 0; i < 3; i++) {
        gl_Position = gl_in[i].gl_Position + vec4(n * spread, 0.0);
        geom_out.uv = geom_in[i].uv;
        EmitVertex();
    }
    EndPrimitive();
}
