#version 330 core
// `flat` and `centroid` on a struct and on arrays: each member takes the variable's
// qualifier (naga's GLSL front passes them member by member). A full-screen triangle whose
// corners differ: flat members come from GL's provoking vertex (the last), smooth ones are
// interpolated with perspective.
struct Tint { vec3 rgb; float weight; };
flat out Tint tint;
flat out vec2 pair[2];
centroid out float ramp[2];
out Tint smooth_tint;

void main()
{
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    float w = 1.0 + float(gl_VertexID) * 0.5;
    tint = Tint(vec3(p * 0.5, 0.25 * float(gl_VertexID)), 0.5);
    pair[0] = p * 0.25;
    pair[1] = vec2(0.2 * float(gl_VertexID), 0.1);
    ramp[0] = p.x * 0.5;
    ramp[1] = p.y * 0.5;
    smooth_tint = Tint(vec3(p.yx * 0.5, 0.1), 1.0);
    gl_Position = vec4((p * 2.0 - 1.0) * w, 0.0, w);
}
