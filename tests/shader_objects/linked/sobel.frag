#version 330 core
// The second shader object of the fragment stage: the helper edge.frag declares.
vec3 sobel(sampler2D image, vec2 at)
{
    vec2 texel = 1.0 / vec2(textureSize(image, 0));
    vec3 dx = texture(image, at + vec2(texel.x, 0.0)).rgb - texture(image, at - vec2(texel.x, 0.0)).rgb;
    vec3 dy = texture(image, at + vec2(0.0, texel.y)).rgb - texture(image, at - vec2(0.0, texel.y)).rgb;
    return sqrt(dx * dx + dy * dy);
}
