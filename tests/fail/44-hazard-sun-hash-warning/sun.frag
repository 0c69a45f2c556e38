#version 330 core

in vert_vars //Receives variables from vertex shader
{
    vec2 outputTexCoords;
    vec3 swirlPosVector;
}frag_in;

out vec4 fragColor;

uniform sampler2D textureSamplerVar;

void main()
{
    vec4 textureColour = texture(textureSamplerVar, frag_in.outputTexCoords); //Assigns data from texture sample
    fragColor = vec4(textureColour.rgb, 1.0); //Outputs the frag colour
}
