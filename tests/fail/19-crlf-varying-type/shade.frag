#version 330 core
// Written on Windows: every line ends in CR LF.
in vec4 vNormal;

out vec4 FragColor;

void main()
{
    FragColor = vec4(normalize(vNormal.xyz) * 0.5 + 0.5, 1.0);
}
