#version 330 core
// FXAA test scene (seed 001): flat colours with hard edges and no antialiasing, so the
// FXAA pass has jaggies to smooth. Each face axis gets its own saturated colour and a
// nearest-filtered checker (no mipmaps) adds diagonal edges inside the faces.

in Vertex
{
    vec3 objectNormal;
    vec2 texCoord;
} IN;

out vec4 fragColour;

uniform sampler2D checkerTex;
uniform vec3 colourX; // faces facing +-x
uniform vec3 colourY; // faces facing +-y
uniform vec3 colourZ; // faces facing +-z

void main(void)
{
    vec3 n = abs(IN.objectNormal);
    vec3 colour = colourZ;
    if(n.x >= n.y && n.x >= n.z)
    {
        colour = colourX;
    }
    else if(n.y >= n.z)
    {
        colour = colourY;
    }
    float checker = texture(checkerTex, IN.texCoord).r; // 1 or 0.1
    fragColour = vec4(colour * checker, 1.0);
}
