#version 410 core
layout(quads, equal_spacing, cw) in;
in vec2 point[];
out vec2 uv;
void main() {
    vec2 u = gl_TessCoord.xy;
    vec2 p = mix(mix(point[0], point[1], u.x), mix(point[3], point[2], u.x), u.y);
    p += 0.08 * vec2(sin(11.0 * p.y), cos(13.0 * p.x));
    uv = u;
    gl_Position = vec4(p, 0.0, 1.0);
}
