#version 330 core
// Matrix vertex inputs take one location per column: GL reads column c at the input's
// location + c, and the translation splits each into column inputs. Both must read the same
// bytes of the mesh.
layout(location = 0) in vec3 position;
layout(location = 1) in mat4 warp;
in mat2 turn;
out vec3 tint;

void main()
{
    tint = abs(warp[0].xyz) * 0.5 + abs(warp[3].xyz) * 0.25 + vec3(abs(turn[1]), 0.0);
    gl_Position = vec4(position.xy * 0.9, 0.0, 1.0);
}
