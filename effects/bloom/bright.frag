#version 330 core
// Bright pass (seed 003, "Bloom Post Processing"): keeps only the parts of the HDR scene
// whose weighted brightness is above bloomThreshold (the seed's hard-coded 1.0), black elsewhere.

uniform sampler2D sceneTex;
uniform float bloomThreshold; // brightness a pixel must exceed to bloom (seed: 1.0)

in Vertex
{
    vec2 texCoord;
} IN;

out vec4 fragColor;

void main(void)
{
    fragColor = vec4(0, 0, 0, 1);

    vec4 diffuse = texture2D(sceneTex, IN.texCoord);
    float brightness = dot(diffuse.rgb, vec3(0.9126, 0.7152, 0.0722));

    if(brightness > bloomThreshold)
    {
        diffuse = vec4(diffuse.rgb, 1.0);
    }
    else
    {
        diffuse = vec4(0.0, 0.0, 0.0, 1.0);
    }

    fragColor = diffuse;
}
