#version 330 core
in vec3 mixes[2];
in mat3 frame_out;
in Tail {
    float clip_sum;
    flat int pick;
} tail;
out vec4 color;
void main() {
    vec3 f = frame_out * vec3(0.5, 0.25, 0.25);
    color = vec4(mixes[0] * 0.5 + mixes[1] * 0.25 + f * 0.25, tail.clip_sum * (1.0 + float(tail.pick)) / 3.0);
}
