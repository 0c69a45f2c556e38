#version 110
uniform sampler2DShadow shadowMap;
uniform vec3 lightColor;

varying vec4 shadowCoord;

void main()
{
    float lit = shadow2DProj(shadowMap, shadowCoord).r;
    gl_FragColor = vec4(lightColor * (0.25 + 0.75 * lit), 1.0);
}
