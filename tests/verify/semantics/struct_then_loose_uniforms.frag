#version 330 core
// A struct uniform followed by loose uniforms, the struct smaller than 16 bytes: WGSL wants
// every member after a struct roundUp(16, size) bytes past it. The translation had laid
// `intensity` 4 bytes after `exposure` (naga refused the module, E0305).
in vec2 uv;
out vec4 color;

struct Exposure { float factor; };
uniform Exposure exposure = Exposure(0.5);
uniform float intensity = 0.25;
uniform vec2 shift = vec2(0.125, 0.375);

void main()
{
    color = vec4(exposure.factor * uv.x, intensity, shift);
}
