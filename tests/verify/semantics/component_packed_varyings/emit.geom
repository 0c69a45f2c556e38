#version 440
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
layout(location = 0) in vec3 in_base[];
layout(location = 0, component = 3) in float in_alpha[];
layout(location = 1) in vec2 in_low[];
layout(location = 1, component = 2) in vec2 in_high[];
layout(location = 0) out vec3 rgb;
layout(location = 0, component = 3) out float a;
layout(location = 3, component = 1) out float lone;
void main() {
    for (int i = 0; i < 3; i++) {
        gl_Position = gl_in[i].gl_Position;
        rgb = in_base[i] + vec3(in_low[i].x, 0.0, in_high[i].y) * 0.5;
        a = in_alpha[i];
        lone = in_high[i].x + in_low[i].y;
        EmitVertex();
    }
}
