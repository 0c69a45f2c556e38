#version 330 core
// Seed 003's lon/lat lookup with the latitude from asin(z), where z is a scaled position:
// with radiusScale above 1, |z| exceeds 1 near the poles and asin returns NaN.
uniform float radiusScale;
in Vertex { vec2 texCoord; } IN;
out vec4 fragColor;
void main() {
    vec2 p = IN.texCoord * 2.0 - 1.0;
    float z = p.y * radiusScale;
    float latitude = asin(z) / 3.14159265 + 0.5;
    float longitude = atan(p.x, 1.0) / 3.14159265 + 0.5;
    fragColor = vec4(longitude, latitude, 0.5, 1.0);
}
