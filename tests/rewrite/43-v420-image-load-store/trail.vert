#version 420 core
// A fragment stage that keeps a trail in one image and reads a mask from another, as GL
// image load/store programs do. Neither image says `readonly` or `writeonly`: WebGPU binds
// read-write storage textures only in 32-bit single-channel formats, so the translation
// gives each image the access its code makes (the mask read-only, the trail write-only).
layout(location = 0) in vec2 aPos;
out vec2 uv;

void main()
{
    uv = aPos * 0.5 + 0.5;
    gl_Position = vec4(aPos, 0.0, 1.0);
}
