// GLSL 1.10, no vertex stage: fog coordinate, secondary colour and the fog state.
void main() {
    float f = clamp((gl_Fog.end - gl_FogFragCoord) * gl_Fog.scale, 0.0, 1.0);
    gl_FragColor = mix(gl_Fog.color, vec4(0.9, 0.6, 0.3, 1.0), f) + gl_SecondaryColor;
}
