#version 400
in vec2 uv;
out vec4 fragColor;

uniform double zoom;
uniform dvec2 center;

void main()
{
    dvec2 p = center + dvec2(uv - 0.5) / zoom;
    fragColor = vec4(vec2(fract(p)), 0.0, 1.0);
}
