#version 330 core
// Built-in calls written inside a function-like macro's argument (`round(modf(x, i))` with
// `#define round(X) floor((X)+0.5)`, as libretro's xBR passes write it) are rewritten where
// they stand: `modf`, which naga lacks, is effectc's at each of its uses.
#define round(X) floor((X)+0.5)
#define twice(X) ((X) * 2.0)
in vec2 uv;
out vec4 color;

void main()
{
    float whole;
    float a = round(modf(uv.x * 7.3, whole));
    float b = twice(modf(uv.y * 3.1, whole)) + round(modf(1.75, whole)) * 0.1;
    color = vec4(a, b * 0.4, whole / 8.0, 1.0);
}
