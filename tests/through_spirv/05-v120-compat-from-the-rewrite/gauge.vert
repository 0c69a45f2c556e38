#version 120
// GLSL 1.20 with fixed-function state: glslang makes no SPIR-V of it as written (below
// 1.40), and naga's GLSL front refuses `band`, which can end without a `return` (legal
// GLSL; the result is undefined past x = 1, which the quad never reaches). So the
// program goes through glslang from effectc's 4.50 rewrite.
varying vec2 uv;

float band(float x)
{
    for (int i = 0; i < 4; i++) {
        if (x <= float(i + 1) * 0.25)
            return float(i) / 3.0;
    }
}

void main()
{
    uv = gl_Vertex.xy * 0.5 + 0.5;
    gl_FrontColor = vec4(band(uv.x), 0.5, 1.0 - band(uv.y), 1.0);
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
