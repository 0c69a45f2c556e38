#version 330 core
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 vNormal;

uniform float time;

void main()
{
    for (int i = 0; i < 3; i++) {
        gl_Position = gl_in[i].gl_Position + vec4(vNormal * time, 0.0);
        EmitVertex();
    }
    EndPrimitive();
}
