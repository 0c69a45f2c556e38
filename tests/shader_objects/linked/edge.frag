#version 330 core
// The helper is declared here and defined by a second shader object.
in vec2 uv;
out vec4 color;
uniform sampler2D scene;
vec3 sobel(sampler2D image, vec2 at);
void main()
{
    color = vec4(sobel(scene, uv), 1.0);
}
