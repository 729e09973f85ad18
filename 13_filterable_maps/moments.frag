#version 330 core
// What a filterable map stores, so that averaging it means something (seed 002: the filter is
// applied to a function of depth, not to the depths a compare needs):
//   VSM  the moments z and z^2 (plus the pixel's own slope in z^2: its depth varies across
//        it, Lauritzen's derivative term), whose averages give a mean and a variance;
//   ESM  exp(c (z - 1)): an average of it is an average of exponentials, which the receiver's
//        exp(-c (t - 1)) turns into a soft compare. (z - 1) keeps the value in (0, 1];
//   MSM  z, z^2, z^3, z^4 through the paper's quantization (msm_math.hpp's encode, affine, so
//        its average is the encoding of the averaged moments).
#include "light_depth.glsl"
in vec3 vWorld;
uniform float uExponent;  // esm.c
uniform mat4 uMomentEncode;  // MSM: msm::encodeMatrix()
uniform float uEncodeOffset;  // MSM: added to the first
out vec4 outMoments;
void main() {
  float z = lightDepth01(vWorld);
#if FILTER_METHOD == FILTER_METHOD_ESM
  outMoments = vec4(exp(uExponent * (z - 1.0)), 0.0, 0.0, 1.0);
#elif FILTER_METHOD == FILTER_METHOD_MSM
  float z2 = z * z;
  outMoments = uMomentEncode * vec4(z, z2, z2 * z, z2 * z2) + vec4(uEncodeOffset, 0.0, 0.0, 0.0);
#else
  float dx = dFdx(z), dy = dFdy(z);
  outMoments = vec4(z, z * z + 0.25 * (dx * dx + dy * dy), 0.0, 1.0);
#endif
}
