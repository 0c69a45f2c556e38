#version 400
// Built-in outputs WebGPU has no use for, on the route through SPIR-V (glslang types them
// in `gl_PerVertex`): `gl_PointSize` and `gl_ClipDistance` are computed, not passed.
layout(location = 0) in vec2 aPos;
out float gl_ClipDistance[1];
out vec2 uv;
void main()
{
    uv = aPos * 0.5 + 0.5;
    gl_PointSize = 4.0;
    gl_ClipDistance[0] = 1.0;
    gl_Position = vec4(aPos, 0.0, 1.0);
}
