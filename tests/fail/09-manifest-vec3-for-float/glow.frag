#version 330 core
in vec2 vUv;

uniform float minBI;
uniform float maxBI;
uniform float time;

out vec4 FragColor;

void main()
{
    float glow = mix(minBI, maxBI, 0.5 + 0.5 * sin(time));
    FragColor = vec4(vec3(glow) * vec3(vUv, 1.0), 1.0);
}
