#version 330 core
// A CRT mask whose menu (RetroArch's `#pragma parameter`) allows a type no branch handles:
// at MASK_TYPE = 0 the mask has no colours, and the phase divides by zero.
#pragma parameter MASK_TYPE "Mask type" 2.0 0.0 3.0 1.0
#pragma parameter MASK_SIZE "Mask size" 1.0 1.0 4.0 1.0
uniform float MASK_TYPE;
uniform float MASK_SIZE;
uniform vec2 OutputSize;
in vec2 uv;
out vec4 colour;

void main() {
    float colours = 0.0;
    if (MASK_TYPE == 1.0) colours = 2.0;
    else if (MASK_TYPE == 2.0) colours = 3.0;
    else if (MASK_TYPE == 3.0) colours = 4.0;
    float x = floor(uv.x * OutputSize.x / MASK_SIZE);
    float phase = mod(x, colours) / colours;
    // Possible only: the range holds 2.5, but no run at MASK_SIZE's default, ends or
    // steps hits it. Reported with `--hazards possible`, not by default.
    float scale = 1.0 / (MASK_SIZE - 2.5);
    colour = vec4(vec3(phase), 1.0) * min(abs(scale), 1.0);
}
