#version 330 core
// Projective encoding: the depth buffer is the map, nothing else is written. Linear encoding
// (000, "Improving Depth Map Precision"): "lookup S in identity 1D intensity texture, write
// texture result into color frame buffer, still using standard depth testing". glPolygonOffset
// does not reach colour, so the same slope-scaled offset is added to S here.
#include "ramp.glsl"
in float vS;
uniform int uLinear;
uniform Ramp uRamp;
uniform float uOffsetFactor;  // glPolygonOffset's factor
uniform float uOffsetSteps;   // and its units, in 8-bit steps
out vec4 outColor;
void main() {
  if (uLinear == 0) {
    outColor = vec4(1.0);
    return;
  }
  float slope = max(abs(dFdx(vS)), abs(dFdy(vS)));
  float s = vS + uOffsetFactor * slope + uOffsetSteps / 255.0;
  outColor = vec4(rampTexel(uRamp, s));
}
