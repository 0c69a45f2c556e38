#version 120
varying float fog;
void main() {
    vec4 lit = gl_Color * (0.75 + 0.25 * sin(gl_TexCoord[0].s * 6.0));
    gl_FragColor = mix(gl_Fog.color, lit, fog);
}
