#version 150
in float a[20];
in vec3 b[6];
in vec2 c[5];
flat in int k[4];
out vec4 frag;
void main() {
    float s = 0.0;
    for (int i = 0; i < 20; i++)
        s += a[i];
    vec3 t = vec3(0.0);
    for (int i = 0; i < 6; i++)
        t += b[i];
    vec2 u = vec2(0.0);
    for (int i = 0; i < 5; i++)
        u += c[i];
    int n = k[0] + k[1] + k[2] + k[3];
    frag = vec4(s / 10.5, t.x / 6.0 + t.z / 10.0, u.x / 3.0 + u.y / 6.0, float(n) / 22.0);
}
