#version 430
// A compute-only program: `render` dispatches it over the frame and shows the image it
// stores to. Red grows to the right, green upward (image row 0 is the picture's bottom).
layout(local_size_x = 8, local_size_y = 4) in;
layout(rgba8, binding = 0) uniform writeonly image2D picture;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(picture);
    if (any(greaterThanEqual(p, size))) {
        return;
    }
    imageStore(picture, p, vec4(float(p.x) / float(size.x - 1), float(p.y) / float(size.y - 1), 0.0, 1.0));
}
