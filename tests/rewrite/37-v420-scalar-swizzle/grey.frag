#version 420 core
in float height;
uniform float ambient;
out vec4 color;
void main()
{
    // GLSL 4.20 swizzles scalars: naga does not, so these become constructors.
    vec3 grey = max(height, ambient).rrr;
    float twice = (height * 2.0).x;
    color = vec4(grey * twice, height.r);
}
