#version 130
in vec3 vNormal;
in vec3 vPos;

void main()
{
    gl_FragData[0] = vec4(vPos, 1.0);
    gl_FragData[1] = vec4(normalize(vNormal) * 0.5 + 0.5, 1.0);
}
