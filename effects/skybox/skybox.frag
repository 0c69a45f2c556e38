#version 330 core
// Skybox, fragment stage (seed 000): samples the cube map along the view direction.
// Below the horizon the cloud map is darkened into a ground colour, so the horizon line
// is visible; envmap.frag applies the same function to its reflected rays.

in vec3 texDir;

out vec4 FragColor;

uniform samplerCube skybox;
uniform vec3 groundColour;   // colour the sky fades to below the horizon

vec3 environment(vec3 dir)
{
    vec3 sky = texture(skybox, dir).rgb;
    float up = dir.y * inversesqrt(max(dot(dir, dir), 1e-12));
    float ground = smoothstep(0.02, -0.08, up);
    return mix(sky, groundColour * (0.4 + 0.8 * sky), ground);
}

void main()
{
    FragColor = vec4(environment(texDir), 1.0);
}
