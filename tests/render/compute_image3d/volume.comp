#version 430
// A compute-only program that stores to a 3D image only: `render` shows its slice 0.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba8, binding = 0) writeonly uniform image3D volume;
void main() {
    ivec3 p = ivec3(gl_GlobalInvocationID);
    imageStore(volume, p, vec4(p.z == 0 ? 1.0 : 0.0, 0.0, 1.0, 1.0));
}
