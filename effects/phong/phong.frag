#version 330 core
// Per-pixel Phong, fragment stage (seed 002): ambient + diffuse + specular with
// R = reflect(-L, N), evaluated per pixel. The point light circles the object:
// its position is computed here from `time` (radius, height and angular speed are uniforms).
// The seed's texture2D / gl_LightSource / gl_TexCoord become texture() and uniforms.

in VS_OUT
{
    vec3 FragPos;
    vec3 Normal;
    vec2 TexCoords;
} fs_in;

out vec4 FragColor;

uniform vec3 viewPos;        // camera position, world space
uniform float time;          // seconds
uniform vec3 lightColor;
uniform vec3 ambientColor;   // material ambient (times light colour)
uniform vec3 diffuseColor;   // material diffuse
uniform vec3 specularColor;  // material specular
uniform float shininess;     // Phong exponent
uniform float lightRadius;   // radius of the light's circle around the y axis
uniform float lightHeight;   // height of that circle
uniform float lightSpeed;    // radians per second
uniform sampler2D colourMap; // modulates the diffuse colour

const float TWO_PI = 6.2831853;

vec3 safeNormalize(vec3 v)
{
    return v * inversesqrt(max(dot(v, v), 1e-12));
}

void main()
{
    // wrapped to [0, 2pi) before sin/cos (W0717): a phase that grows with time loses f32
    // precision after hours; fract(x / TWO_PI) * TWO_PI is mod(x, TWO_PI)
    float angle = fract(time * lightSpeed / TWO_PI) * TWO_PI;
    vec3 lightPos = vec3(lightRadius * cos(angle), lightHeight, lightRadius * sin(angle));

    vec3 N = safeNormalize(fs_in.Normal);
    vec3 L = safeNormalize(lightPos - fs_in.FragPos);
    vec3 V = safeNormalize(viewPos - fs_in.FragPos);

    vec3 albedo = texture(colourMap, fs_in.TexCoords).rgb;

    // ambient
    vec3 ambient = ambientColor * lightColor * albedo;
    // diffuse
    float diff = max(dot(N, L), 0.0);
    vec3 diffuse = diff * diffuseColor * lightColor * albedo;
    // specular (only on the lit side)
    vec3 R = reflect(-L, N);
    float spec = diff > 0.0 ? pow(max(dot(R, V), 0.0), max(shininess, 1.0)) : 0.0;
    vec3 specular = spec * specularColor * lightColor;

    FragColor = vec4(ambient + diffuse + specular, 1.0);
}
