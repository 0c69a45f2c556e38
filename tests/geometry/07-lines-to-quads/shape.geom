#version 330 core
// A band along each input line, coloured by which edge of its triangle it is.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
in vec3 vColor[];
out vec3 color;
void main() {
    vec2 d = gl_in[1].gl_Position.xy - gl_in[0].gl_Position.xy;
    vec4 side = vec4(-d.y, d.x, 0.0, 0.0) * 0.125;
    int edge = gl_PrimitiveIDIn % 3;
    color = edge == 0 ? vec3(1.0, 0.0, 0.0) : (edge == 1 ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0));
    gl_Position = gl_in[0].gl_Position - side; EmitVertex();
    gl_Position = gl_in[1].gl_Position - side; EmitVertex();
    gl_Position = gl_in[0].gl_Position + side; EmitVertex();
    gl_Position = gl_in[1].gl_Position + side; EmitVertex();
    EndPrimitive();
}
