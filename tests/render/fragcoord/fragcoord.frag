#version 330 core
// GL conventions that WebGPU turns around: gl_FragCoord's origin is the bottom-left pixel
// and dFdy grows upward. Red: the bottom half by gl_FragCoord; green: dFdy(uv.y) > 0;
// blue: the bottom half by uv.
in vec2 uv;
out vec4 fragColor;
uniform vec2 resolution;
void main()
{
    float bottomByFragCoord = gl_FragCoord.y < 0.5 * resolution.y ? 1.0 : 0.0;
    float upwardDerivative = dFdy(uv.y) > 0.0 ? 1.0 : 0.0;
    float bottomByUv = uv.y < 0.5 ? 1.0 : 0.0;
    fragColor = vec4(bottomByFragCoord, upwardDerivative, bottomByUv, 1.0);
}
