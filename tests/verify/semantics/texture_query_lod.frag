#version 450 core
// textureQueryLod (GLSL 4.30; 4.00 named it textureQueryLOD), which naga and WGSL lack: the level of detail from the coordinates'
// derivatives in texels (.y), clamped to the texture's levels (.x), as GL defines it;
// magnified (negative λ, .x clamped to 0), minified, and on a texture array (its coordinates name no layer).
uniform sampler2D tex;
uniform sampler2DArray layers;
in vec2 uv;
out vec4 color;

void main()
{
    vec2 magnified = textureQueryLod(tex, uv * 0.25);
    vec2 minified = textureQueryLod(tex, uv * 5.0 + uv.yx * uv.x);
    vec2 layered = textureQueryLod(layers, uv * 3.0);
    color = vec4(magnified.x + (magnified.y + 8.0) / 16.0, minified.x / 8.0, (minified.y + 2.0) / 8.0, layered.y / 8.0 + 0.25);
}
