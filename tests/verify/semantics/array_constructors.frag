#version 330 core
// Array constructors, .length(), dynamic indexing of a const array.
in vec2 uv;
out vec4 color;

const vec3 palette[4] = vec3[4](vec3(1.0, 0.0, 0.0), vec3(0.0, 1.0, 0.0), vec3(0.0, 0.0, 1.0), vec3(1.0, 1.0, 0.0));

void main()
{
    int i = int(gl_FragCoord.x / 16.0) % palette.length();
    float w[] = float[](0.25, 0.5, 0.75);
    color = vec4(palette[i] * w[int(gl_FragCoord.y) % w.length()], 1.0);
}
