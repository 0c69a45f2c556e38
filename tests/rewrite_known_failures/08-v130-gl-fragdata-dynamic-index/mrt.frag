#version 130
uniform int target;

void main()
{
    gl_FragData[0] = vec4(0.0);
    gl_FragData[1] = vec4(0.0);
    gl_FragData[target] = vec4(1.0, 0.0, 0.0, 1.0);
}
