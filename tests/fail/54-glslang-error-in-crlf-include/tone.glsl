// Tone curve shared by the effects.
vec3 tone(vec3 c)
{
    float k = 2;
    return c * k / (c * k + 1.0);
}
