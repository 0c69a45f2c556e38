#version 330 core
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in Corner {
    vec4 ramp[3];
    float weight;
} corner[];
in Plain {
    mat3 frame;
} plain[];
out vec3 mixes[2];
out mat3 frame_out;
out Tail {
    float clip_sum;
    flat int pick;
} tail;
void main() {
    for (int v = 0; v < 3; v++) {
        gl_Position = gl_in[v].gl_Position;
        int k = v % 3;
        mixes[0] = corner[v].ramp[k].rgb * corner[v].weight;
        mixes[1] = corner[v].ramp[2 - k].gba;
        frame_out = plain[v].frame;
        tail.clip_sum = (gl_in[v].gl_ClipDistance[0] + gl_in[v].gl_ClipDistance[1] + gl_in[v].gl_PointSize) / 16.0;
        tail.pick = v;
        EmitVertex();
    }
    EndPrimitive();
}
