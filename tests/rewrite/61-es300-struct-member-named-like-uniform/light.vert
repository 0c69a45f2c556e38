#version 300 es

in vec3 position;
out vec3 normal;

void main()
{
    normal = normalize(position + vec3(0.0, 0.0, 1.0));
    gl_Position = vec4(position, 1.0);
}
