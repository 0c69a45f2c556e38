float shade(vec3 n) {
    return dot(n, vec3(0.0, 1.0));
}
