#version 330 core

out vert_vars //Declaration of output variables that will be passed to fragment shader
{
    vec2 outputTexCoords;
}vert_out;

layout(location = 0) in vec3 vertPosition; //Declaration of layout variables
layout(location = 1) in vec2 vertTexCoords;

uniform mat4 model; //Declaration of uniform variables, defined in main class
uniform mat4 view;
uniform mat4 projection;

void main()
{
    gl_Position = projection * view * model * vec4(vertPosition, 1.0);
    vert_out.outputTexCoords = vertTexCoords;
}
