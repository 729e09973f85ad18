// The singular values of the 2x2 Jacobian of a pixel's map texel coordinates (the texels one
// screen pixel spans along its most and its least sampled direction), largest first, as
// singularValues() in common/math/texel_density.cpp: s1^2 + s2^2 = |J|^2, s1 s2 = |det J|.
// The runner's texel pass (texel_density.frag) and lesson 11's faces, which are no one 2D map.
vec2 singularValues(vec2 ddx, vec2 ddy) {
  float frob = dot(ddx, ddx) + dot(ddy, ddy);
  float det = abs(ddx.x * ddy.y - ddy.x * ddx.y);
  float big = sqrt(0.5 * (frob + sqrt(max(frob * frob - 4.0 * det * det, 0.0))));
  return vec2(big, big > 0.0 ? det / big : 0.0);
}
