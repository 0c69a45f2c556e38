#version 400 core
// Per-pixel Phong renormalizes the interpolated normal. Between a vertex whose normal is +z
// and one whose normal is -z (the mesh's flipped normal) the interpolated vNormal crosses
// the zero vector, and normalize(0) is NaN. textureGather (GLSL 4.00), which naga's GLSL front
// does not know, sends the program through SPIR-V: the warning must still name this line.
in vec3 vNormal;

out vec4 FragColor;

uniform vec3 lightDir;
uniform sampler2D veins;

void main()
{
    vec3 n = normalize(vNormal);
    float diffuse = max(dot(n, normalize(lightDir)), 0.0);
    float vein = textureGather(veins, vec2(0.5)).x;
    FragColor = vec4(vec3(0.2, 0.6, 0.15) * (0.2 + 0.8 * diffuse) * vein, 1.0);
}
