#version 330 core
layout(location = 0) in vec2 aGrid;

uniform sampler2D heightMap;
uniform float heightScale;
uniform mat4 mvp;

out float vHeight;

void main()
{
    float h = texture(heightMap, aGrid).r * heightScale;
    vHeight = h;
    gl_Position = mvp * vec4(aGrid.x, h, aGrid.y, 1.0);
}
