#version 410 core

// The built-in output block redeclared with an unsized clip-distance array: GL sizes it
// from the largest index the stage writes.
out gl_PerVertex
{
    vec4 gl_Position;
    float gl_PointSize;
    float gl_ClipDistance[];
};

layout(location = 0) in vec3 position;
layout(location = 0) out vec3 shade;

uniform mat4 mvp;
uniform vec4 plane;

void main()
{
    vec4 p = vec4(position, 1.0);
    gl_Position = mvp * p;
    gl_ClipDistance[0] = dot(p, plane);
    shade = position * 0.5 + 0.5;
}
