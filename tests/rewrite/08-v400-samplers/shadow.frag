#version 400
in vec4 vLightPos;
in vec3 vNormal;

uniform sampler2D albedo;
uniform samplerCube sky;
uniform sampler2DShadow shadowMap;

out vec4 fragColor;

void main()
{
    vec3 p = vLightPos.xyz / vLightPos.w * 0.5 + 0.5;
    float lit = texture(shadowMap, vec3(p.xy, p.z - 0.005));
    vec3 base = texture(albedo, p.xy).rgb;
    vec3 env = texture(sky, normalize(vNormal)).rgb;
    fragColor = vec4(base * (0.3 + 0.7 * lit) + 0.1 * env, 1.0);
}
