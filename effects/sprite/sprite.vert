#version 330 core
// Billboarded sprite (seed 001): the rotation part of the model-view matrix is replaced by
// the model's scale, so the quad always faces the camera, whatever the model rotation and
// wherever the camera is.

layout(location = 0) in vec3 aPos;
layout(location = 1) in vec2 aTexCoord;

out vec2 TexCoord;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

void main()
{
    // Scale of each model axis (length of the model matrix's columns).
    vec3 modelScale = vec3(length(model[0].xyz), length(model[1].xyz), length(model[2].xyz));

    mat4 modelView = view * model;
    // (whole columns are assigned: naga's GLSL front rejects `modelView[0].xyz = …`)
    modelView[0] = vec4(modelScale.x, 0.0, 0.0, modelView[0].w);
    modelView[1] = vec4(0.0, modelScale.y, 0.0, modelView[1].w);
    modelView[2] = vec4(0.0, 0.0, modelScale.z, modelView[2].w);

    TexCoord = aTexCoord;
    gl_Position = projection * modelView * vec4(aPos, 1.0);
}
