#version 450
// `utexture2D` (glsl-lang's grammar lacks the unsigned texture types) read with texelFetch.
layout(set = 0, binding = 0) uniform utexture2D ids;
layout(set = 0, binding = 1) uniform sampler nearest;
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 colour;
void main() {
    uvec4 id = texelFetch(usampler2D(ids, nearest), ivec2(uv * 4.0), 0);
    colour = vec4(id) / 255.0;
}
