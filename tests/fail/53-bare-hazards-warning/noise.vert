#version 330 core
// Bare stage files, no manifest: effectc guesses what the renderer does (iTime is the
// time over a day, iResolution the frame size), so the hazards below are still found.
layout(location = 0) in vec2 aPos;
out vec2 uv;
void main() {
    uv = aPos * 0.5 + 0.5;
    gl_Position = vec4(aPos, 0.0, 1.0);
}
