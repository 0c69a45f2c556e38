#version 330 core
layout(location = 0) in vec3 aPos;
layout(location = 1) in vec3 aColor;
out Vertex {
    flat vec3 faceColor;
    noperspective vec2 screen;
    centroid vec2 uv;
} vs_out;
void main()
{
    vs_out.faceColor = aColor;
    vs_out.screen = aPos.xy;
    vs_out.uv = aPos.xy * 0.5 + 0.5;
    gl_Position = vec4(aPos, 1.0);
}
