#version 330 core
// Swizzled reads and writes, repeated components, chained swizzles.
in vec2 uv;
out vec4 color;

void main()
{
    vec4 v = vec4(uv, 0.25, 0.75);
    v.zx = v.xw;
    vec3 w = v.wzy.yxz;
    v.y = w.x;
    color = vec4(v.xxz.yz, w.z, v.y);
}
