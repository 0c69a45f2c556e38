#version 330 core
struct Tint { vec3 colour; float gain; };
uniform Tint tint = Tint(vec3(1.0, 0.5, 0.2), 2.0);

out vec4 FragColor;

void main()
{
    FragColor = vec4(tint.colour * tint.gain, 1.0);
}
