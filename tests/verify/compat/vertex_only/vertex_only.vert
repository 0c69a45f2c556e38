#version 120
// A vertex stage alone: GL draws it with its fixed-function fragment processing (the
// interpolated primary colour). Its arrays compared whole, which naga's GLSL front does
// not take, send it through glslang's SPIR-V from effectc's rewrite.
float[3] steps(vec2 p)
{
    return float[3](step(0.0, p.x), step(0.0, p.y), step(0.0, p.x * p.y));
}

void main()
{
    float[3] s = steps(gl_Vertex.xy);
    vec3 c = gl_Vertex.xyz * 0.5 + 0.5;
    if (s == float[3](1.0, 1.0, 1.0))
        c = c.bgr;
    gl_FrontColor = vec4(c, 1.0);
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
