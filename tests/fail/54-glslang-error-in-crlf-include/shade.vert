#version 110
// GLSL 1.10 has no implicit int -> float conversion: a GL 2.0 driver refuses `float k = 2;`
attribute vec3 position;
attribute vec3 color;
varying vec3 col;
void main()
{
    col = color;
    gl_Position = vec4(position, 1.0);
}
