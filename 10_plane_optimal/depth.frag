#version 330 core
// DEPTH_REPLACE (Trapezoidal Shadow Maps, cited by seed 002): store the light's linear depth
// along its axis instead of the projection's z/w, so a warp changes where texels land and
// nothing about depth precision. Without it the warp's own z/w is stored.
in vec3 vWorld;
uniform vec4 uDepthPlane;  // dot(xyz, p) + w: 0 at the light's near plane, 1 at its far plane
void main() {
#if DEPTH_REPLACE
  gl_FragDepth = clamp(dot(uDepthPlane.xyz, vWorld) + uDepthPlane.w, 0.0, 1.0);
#endif
}
