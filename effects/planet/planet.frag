#version 330 core
// Planet surface (seed 003): the colour is looked up by longitude/latitude computed from the
// object-space direction, and a second noise texture scrolls over it in longitude as clouds,
// blended with an alpha taken from the noise value.

in VS_OUT
{
    vec3 objectDir;
    vec3 worldNormal;
} fs_in;

out vec4 FragColor;

uniform sampler2D surfaceMap;
uniform sampler2D cloudMap;
uniform float time;
uniform float sunAzimuth;   // radians around +y, 0 = +z (towards the camera)
uniform float sunElevation; // radians above the equator plane
uniform float seaLevel;
uniform float cloudSpeed;
uniform float cloudCover;
uniform float cloudSoftness;
uniform float polarCap;
uniform float ambient;

const float PI = 3.14159265;

vec3 safeNormalize(vec3 v, vec3 fallback)
{
    float len = length(v);
    return len > 1e-6 ? v / len : fallback;
}

void main()
{
    vec3 dir = safeNormalize(fs_in.objectDir, vec3(0.0, 1.0, 0.0));

    // Longitude in [0, 1): atan is undefined at (0, 0), which only happens at the poles.
    float horizontal = length(dir.xz);
    float lon = horizontal > 1e-6 ? atan(dir.z, dir.x) / (2.0 * PI) + 0.5 : 0.0;
    // Latitude in [0, 1]: asin argument clamped (interpolation can push |y| past 1).
    float lat = asin(clamp(dir.y, -1.0, 1.0)) / PI + 0.5;
    vec2 lonLat = vec2(lon, lat);

    // Surface: height from the continent noise, coloured ocean / beach / forest / mountain.
    float h = texture(surfaceMap, lonLat).r;
    vec3 deepSea = vec3(0.01, 0.05, 0.25);
    vec3 shallowSea = vec3(0.05, 0.25, 0.55);
    vec3 sand = vec3(0.76, 0.70, 0.45);
    vec3 forest = vec3(0.12, 0.42, 0.10);
    vec3 rock = vec3(0.45, 0.35, 0.25);
    vec3 surface;
    if (h < seaLevel)
    {
        surface = mix(deepSea, shallowSea, smoothstep(seaLevel - 0.15, seaLevel, h));
    }
    else
    {
        float land = h - seaLevel;
        surface = mix(sand, forest, smoothstep(0.0, 0.03, land));
        surface = mix(surface, rock, smoothstep(0.1, 0.22, land));
    }
    // Ice caps towards the poles.
    float ice = smoothstep(polarCap, polarCap + 0.06, abs(dir.y) + (h - 0.5) * 0.2);
    surface = mix(surface, vec3(0.92, 0.95, 1.0), ice);

    // Clouds: the same lon/lat, scrolled in longitude over time (the texture repeats).
    vec2 cloudUV = lonLat + vec2(time * cloudSpeed, 0.0);
    float c = texture(cloudMap, cloudUV).r;
    float cloudAlpha = smoothstep(cloudCover, cloudCover + max(cloudSoftness, 1e-3), c);
    vec3 colour = mix(surface, vec3(1.0), cloudAlpha * 0.9);

    // Day/night lighting from a fixed sun.
    vec3 n = safeNormalize(fs_in.worldNormal, vec3(0.0, 1.0, 0.0));
    vec3 l = vec3(cos(sunElevation) * sin(sunAzimuth), sin(sunElevation), cos(sunElevation) * cos(sunAzimuth)); // unit length
    float diffuse = max(dot(n, l), 0.0);
    vec3 lit = colour * (ambient + diffuse);
    // A thin blue rim (atmosphere) on the lit side.
    lit += vec3(0.1, 0.2, 0.45) * pow(max(1.0 - abs(n.z), 0.0), 3.0) * (0.3 + diffuse);

    FragColor = vec4(lit, 1.0);
}
