#version 330 core
// Interpolation qualifiers on block members must survive translation: naga's GLSL
// parser drops them, effectc puts them back on the bindings.
in Vertex {
    flat vec3 faceColor;
    noperspective vec2 screen;
    centroid vec2 uv;
} fs_in;
out vec4 color;
void main()
{
    color = vec4(fs_in.faceColor * (0.5 + 0.5 * fs_in.screen.x) + vec3(fs_in.uv, 0.0) * 0.1, 1.0);
}
