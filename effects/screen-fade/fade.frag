#version 330 core
// Screen fade by camera height (seed 001, "a post-processing shader, which fades the
// screen to a green colour as the camera enters the clouds ... using the world position
// of the camera, and fading to green the higher the camera is"): below fadeStart the scene
// is untouched, above fadeEnd it is all fadeColour, linear in between.

uniform sampler2D sceneTex;
uniform vec3 cameraPos;   // world-space camera position
uniform float fadeStart;  // camera height where the fade begins
uniform float fadeEnd;    // camera height where the screen is fully fadeColour
uniform vec3 fadeColour;  // the seed fades to green

in Vertex
{
    vec2 texCoord;
} IN;

out vec4 fragColour;

void main(void)
{
    vec3 scene = texture(sceneTex, IN.texCoord).rgb;

    // Guard: fadeEnd <= fadeStart (possible within the ranges) would divide by zero or
    // invert the ramp; a span of at least 1e-4 turns that into a hard switch at fadeStart.
    float span = max(fadeEnd - fadeStart, 1e-4);
    float fade = clamp((cameraPos.y - fadeStart) / span, 0.0, 1.0);

    fragColour = vec4(mix(scene, fadeColour, fade), 1.0);
}
