#version 330 core
// Single-direction bloom blur (seed 003, "Bloom Post Processing"): bloomRange taps along
// one axis (isVertical = 0: x, 1: y), one texel apart, weighted by the seed's curve
// 1 / 2^|-8 + 16 * z / (range - 1)| (1 at the centre tap, 1/256 at the ends), times
// bloomIntensity. Run twice: once horizontally, once vertically.

uniform sampler2D sceneTex;

uniform int isVertical;
uniform int bloomRange;
uniform float bloomIntensity;
in Vertex
{
	vec2 texCoord;
} IN;

out vec4 fragColor;

void main(void)
{
	fragColor = vec4(0, 0, 0, 1);
	vec2 delta = vec2(0, 0);

	if(isVertical == 1)
	{
		delta = dFdy(IN.texCoord);
	}
	else
	{
		delta = dFdx(IN.texCoord);
	}
	float z = 0;
	int ranger = bloomRange;
	float startCurve = 8.0f;

	// Guard (not in the seed): the curve divides by (ranger-1), which is 0 when
	// bloomRange == 1. A single tap is the centre of the curve, so use a step of 0 and
	// start the curve at 0 there (weight 1) instead of dividing by zero.
	float curveStart = startCurve;
	float curveStep = 0.0;
	if(ranger > 1)
	{
		curveStep = (startCurve*2)/(ranger-1);
	}
	else
	{
		curveStart = 0.0;
	}

	for(int i = 0; i < ranger; i++)
	{
		// (ranger-1)/2 is an integer division, as in the seed: centred for odd ranges
		vec2 offset = delta * (z - (ranger-1)/2);
		vec4 tmp = texture2D(sceneTex, IN.texCoord.xy + offset);

		float curve = 1.0/(pow(2.0,
		abs(

		-curveStart + curveStep * z

		)
		));
		fragColor += tmp * curve * bloomIntensity;
		z+=1.0;
	}
}
