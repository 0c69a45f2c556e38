#version 330 core
// A matrix column chosen at run time, written through an index.
in vec2 uv;
out vec4 color;

void main()
{
    mat3 m = mat3(uv.x);
    int c = int(gl_FragCoord.y) % 3;
    m[c] = vec3(uv.y, 0.5, 0.25);
    m[c][(c + 1) % 3] += 0.125;
    color = vec4(m[0].x, m[1].y, m[2].z, m[c][c]);
}
