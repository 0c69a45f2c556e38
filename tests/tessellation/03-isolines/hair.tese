#version 410 core
layout(isolines, equal_spacing) in;
out float along;
void main() {
    vec4 a = mix(gl_in[0].gl_Position, gl_in[1].gl_Position, gl_TessCoord.x);
    vec4 b = mix(gl_in[3].gl_Position, gl_in[2].gl_Position, gl_TessCoord.x);
    vec4 p = mix(a, b, gl_TessCoord.y);
    p.y += 0.1 * sin(12.0 * p.x);
    along = gl_TessCoord.x;
    gl_Position = p;
}
