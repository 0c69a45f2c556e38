#version 330 core
// isnan and isinf of computed infinities (1/0 of a runtime zero).
in vec2 uv;
out vec4 color;

void main()
{
    float z = floor(uv.x * 2.0);
    float inf = 1.0 / z;
    color = vec4(float(isinf(inf)), float(isnan(inf - inf)), float(isinf(-inf)), 1.0);
}
