#version 330 core
uniform sampler2D sprite;
out vec4 fragColor;
void main()
{
    vec2 fromCentre = gl_PointCoord - vec2(0.5);
    if (dot(fromCentre, fromCentre) > 0.25)
        discard;
    fragColor = texture(sprite, gl_PointCoord);
}
