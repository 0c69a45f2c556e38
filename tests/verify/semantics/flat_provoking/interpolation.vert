#version 330 core
// A full-screen triangle whose corners have different w: `flat` values come from GL's
// provoking vertex (the last), the others are interpolated with perspective.
// (`noperspective` next to `flat` inputs draws differently on llvmpipe's GL and
// lavapipe, both unlike the GLSL rule: left out here until a third driver can tell.)
flat out int corner;
flat out vec3 tint;
out float perspective;

void main()
{
    vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    float w = 1.0 + float(gl_VertexID) * 0.5;
    corner = gl_VertexID;
    tint = vec3(p * 0.5, 0.25 * float(gl_VertexID));
    perspective = p.y * 0.5;
    gl_Position = vec4((p * 2.0 - 1.0) * w, 0.0, w);
}
