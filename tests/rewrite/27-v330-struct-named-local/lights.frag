#version 330
struct Attenuation { float Constant; float Linear; float Exp; };
struct BaseLight { vec3 Color; float AmbientIntensity; float DiffuseIntensity; };
struct PointLight { BaseLight Base; vec3 Position; Attenuation Atten; };
uniform PointLight gPointLights[2];

out vec4 FragColor;
vec4 CalcPointLight(PointLight l) {
  float Distance = length(l.Position);
  float Attenuation = l.Atten.Constant + l.Atten.Linear * Distance;
  return vec4(l.Base.Color, 1.0) / Attenuation;
}
void main() { vec4 c = vec4(0.0); c += CalcPointLight(gPointLights[0]) + CalcPointLight(gPointLights[1]); FragColor = c; }
