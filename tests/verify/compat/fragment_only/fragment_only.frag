#version 120
// No vertex stage: GL runs its fixed-function vertex processing (identity matrices).
void main() {
    vec2 cell = floor(gl_FragCoord.xy / 8.0);
    float checker = mod(cell.x + cell.y, 2.0);
    gl_FragColor = vec4(gl_TexCoord[0].st, checker, 1.0) * gl_Color;
}
