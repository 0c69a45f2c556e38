#version 330 core
// Instanced particles (seed 001): one quad per instance, placed at the instance's offset,
// rising with time and wrapping at riseHeight (bubbles), and built from the camera's right
// and up vectors so every particle faces the camera.

layout(location = 0) in vec3 aPos;      // quad corner, -0.5..0.5 in xy
layout(location = 1) in vec2 aTexCoord;
layout(location = 2) in vec3 aOffset;   // per instance
layout(location = 3) in float aPhase;   // per instance
layout(location = 4) in float aSize;    // per instance

out vec2 TexCoord;
out float Fade;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform float time;
uniform float riseSpeed;
uniform float riseHeight;
uniform float swayAmount;
uniform float swayFrequency;
uniform float particleSize;

void main()
{
    float height = max(riseHeight, 0.01);

    // Each particle rises at its own speed and wraps back to the bottom of the column.
    float speed = riseSpeed * (0.75 + 0.25 * sin(aPhase * 3.0));
    float y = mod(aOffset.y + time * speed, height);
    float t = y / height;                       // 0 at the bottom, 1 at the top

    vec3 center = vec3(aOffset.x + swayAmount * sin(time * swayFrequency + aPhase),
                       y,
                       aOffset.z + swayAmount * cos(time * swayFrequency * 0.7 + aPhase));
    vec3 worldCenter = (model * vec4(center, 1.0)).xyz;

    // Camera right and up in world space: the first two rows of the view matrix's rotation.
    vec3 cameraRight = vec3(view[0][0], view[1][0], view[2][0]);
    vec3 cameraUp = vec3(view[0][1], view[1][1], view[2][1]);

    float size = particleSize * aSize * (0.6 + 0.4 * t);   // bubbles grow as they rise
    vec3 worldPos = worldCenter + (cameraRight * aPos.x + cameraUp * aPos.y) * size;

    // Fade in at the bottom and out at the top so the wrap is not visible.
    Fade = smoothstep(0.0, 0.12, t) * (1.0 - smoothstep(0.8, 1.0, t));
    TexCoord = aTexCoord;
    gl_Position = projection * view * vec4(worldPos, 1.0);
}
