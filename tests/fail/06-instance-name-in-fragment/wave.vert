#version 410 core
layout(location = 0) in vec3 position;

out VertexData {
    vec3 color;
    float height;
} vert_out;

uniform float time;

void main()
{
    float h = sin(position.x * 4.0 + time) * 0.1;
    vert_out.color = vec3(0.2, 0.5, 0.9);
    vert_out.height = h;
    gl_Position = vec4(position.x, position.y + h, position.z, 1.0);
}
