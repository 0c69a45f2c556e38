#version 150
// More varyings than WebGPU has locations (16; GL packs them four components to a
// location): scalars, 2- and 3-vectors and flat integers share 4-vectors in the
// translation, a 3-vector straddling two of them.
in vec4 position;
out float a[20];
out vec3 b[6];
out vec2 c[5];
flat out int k[4];
void main() {
    gl_Position = position;
    vec2 p = position.xy * 0.5 + 0.5;
    for (int i = 0; i < 20; i++)
        a[i] = p.x * float(i + 1) / 20.0;
    for (int i = 0; i < 6; i++)
        b[i] = vec3(p.y, p.x * 0.5, float(i) / 6.0);
    for (int i = 0; i < 5; i++)
        c[i] = p.yx * float(5 - i) / 5.0;
    for (int i = 0; i < 4; i++)
        k[i] = i * 3 + 1;
}
