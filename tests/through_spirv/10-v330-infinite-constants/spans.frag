#version 330 core

// Distances start at infinity, as ray casters and deferred renderers write them.
const float INF = 1.0 / 0.0;
const vec2 EVERYWHERE = vec2(-1.0 / 0.0, 1.0 / 0.0);

uniform float time;
in vec2 uv;
out vec4 color;

void main()
{
    vec2 p = uv * 2.0 - 1.0;
    float nearest = INF;
    vec2 span = EVERYWHERE;
    for (int i = 0; i < 3; i++) {
        vec2 c = 0.5 * vec2(cos(float(i) * 2.1 + time), sin(float(i) * 2.1 + time));
        nearest = min(nearest, length(p - c) - 0.2);
        span = vec2(max(span.x, p.x - c.x), min(span.y, p.y - c.y));
    }
    float undefined = 0.0 / 0.0;
    float flags = (isnan(undefined) ? 0.25 : 0.0) + (isinf(INF) && span.x > -INF ? 0.5 : 0.0);
    color = vec4(smoothstep(0.02, 0.0, nearest), clamp(span.y - span.x, 0.0, 1.0), flags, 1.0);
}
