#version 130
// A redeclared gl_ClipDistance keeps its size (length() is 3, not the maximum). The
// distances are positive everywhere: nothing is clipped whether or not a plane is enabled
// (Mesa's llvmpipe clips by written distances even with every GL_CLIP_DISTANCEi disabled).
out float gl_ClipDistance[3];
void main()
{
    gl_Position = gl_Vertex;
    for (int i = 0; i < gl_ClipDistance.length(); i++) {
        gl_ClipDistance[i] = 2.0 + gl_Vertex.x + float(i);
    }
    gl_FrontColor = vec4(float(gl_ClipDistance.length()) / 4.0, gl_Vertex.xy * 0.5 + 0.5, 1.0);
}
