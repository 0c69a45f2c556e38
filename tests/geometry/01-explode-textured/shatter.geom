#version 420 core
// Each triangle moves along its face normal by an amount that swings with time.
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 shadeNormal[];
in Surface {
    vec2 uv;
} surfaceIn[];
out Shaded {
    vec2 uv;
    float light;
} shaded;
uniform float time;
uniform float spread;
vec3 faceNormal() {
    vec3 a = gl_in[1].gl_Position.xyz - gl_in[0].gl_Position.xyz;
    vec3 b = gl_in[2].gl_Position.xyz - gl_in[0].gl_Position.xyz;
    return normalize(cross(a, b));
}
void main() {
    vec3 n = faceNormal();
    float push = (sin(time) + 1.0) * 0.5 * spread;
    for (int i = 0; i < 3; i++) {
        gl_Position = gl_in[i].gl_Position + vec4(n * push, 0.0);
        shaded.uv = surfaceIn[i].uv;
        shaded.light = max(dot(normalize(shadeNormal[i]), vec3(0.0, 0.0, 1.0)), 0.2);
        EmitVertex();
    }
    EndPrimitive();
}
