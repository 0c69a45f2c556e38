#version 330 core
layout(points) in;
layout(triangle_strip, max_vertices = 4) out;
in vec4 pointColor[];
uniform mat4 projection;
uniform float size;
out vec2 corner;
flat out vec4 tint;
void main() {
    vec4 center = gl_in[0].gl_Position;
    // Alternate sprites are tinted darker: the primitive id reaches the geometry stage.
    float shade = (gl_PrimitiveIDIn % 2 == 0) ? 1.0 : 0.5;
    for (int i = 0; i < 4; i++) {
        vec2 offset = vec2(i % 2, i / 2) * 2.0 - 1.0;
        corner = offset;
        tint = pointColor[0] * shade;
        gl_Position = projection * (center + vec4(offset * size, 0.0, 0.0));
        EmitVertex();
    }
    EndPrimitive();
}
