#version 330 core
// Bloom combine (seed 003, "All that was left was to add the final result to the base
// image"): the blurred bright parts added onto the scene.

uniform sampler2D sceneTex;
uniform sampler2D bloomTex;

in Vertex
{
    vec2 texCoord;
} IN;

out vec4 fragColor;

void main(void)
{
    vec3 scene = texture(sceneTex, IN.texCoord).rgb;
    vec3 bloom = texture(bloomTex, IN.texCoord).rgb;
    fragColor = vec4(scene + bloom, 1.0);
}
