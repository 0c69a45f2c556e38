#version 150
flat in ivec4 f[31];
out vec4 frag;
void main() {
    int wrong = 0;
    for (int i = 0; i < 31; i++)
        if (f[i] != ivec4(i * 4, i * 4 + 1, i * 4 + 2, i * 4 + 3))
            wrong++;
    frag = vec4(float(wrong) / 31.0, 1.0 - float(wrong) / 31.0, gl_FragCoord.x / 64.0, 1.0);
}
