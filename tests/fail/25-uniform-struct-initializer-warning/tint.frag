#version 330 core
// A struct with an array member: naga's uniform layout gives the member another array
// type than the constructor's, so effectc cannot read this initializer.
struct Tint { vec3 colour; float gains[2]; };
uniform Tint tint = Tint(vec3(1.0, 0.5, 0.2), float[2](2.0, 0.5));

out vec4 FragColor;

void main()
{
    FragColor = vec4(tint.colour * tint.gains[0] * tint.gains[1], 1.0);
}
