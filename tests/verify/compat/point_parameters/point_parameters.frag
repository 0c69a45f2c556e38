#version 120
void main() { gl_FragColor = vec4(gl_Point.size * 0.5, gl_Point.sizeMin + 0.25, gl_Point.fadeThresholdSize * 0.75, gl_Point.distanceConstantAttenuation) + vec4(gl_Point.distanceLinearAttenuation, gl_Point.distanceQuadraticAttenuation, 0.0, 0.0); }
