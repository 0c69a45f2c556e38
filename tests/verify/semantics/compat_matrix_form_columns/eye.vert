#version 120
// A column of a matrix form (`gl_ModelViewMatrixInverse[3]`: the eye's position in object
// space) next to a matrix of the texture-matrix array taken in a form
// (`gl_TextureMatrixInverse[0]`, whose column 1 is read).
varying vec3 eye;

void main()
{
    eye = gl_ModelViewMatrixInverse[3].xyz + gl_TextureMatrixInverse[0][1].xyz;
    gl_Position = ftransform();
}
