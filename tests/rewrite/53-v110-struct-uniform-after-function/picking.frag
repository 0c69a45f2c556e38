#version 110
// A loose uniform read by a function that comes before the struct of another uniform:
// effectc's uniform block must follow the struct and precede the function, so the struct
// moves up with the block.
uniform float picking;

vec4 shade(vec4 c)
{
    if (picking > 0.5)
        return vec4(1.0, 0.0, 1.0, 1.0);
    return c;
}

struct Fog { vec4 color; float density; };
uniform Fog fog;

void main()
{
    float f = exp(-fog.density * gl_FragCoord.z);
    gl_FragColor = shade(mix(fog.color, gl_Color, f));
}
