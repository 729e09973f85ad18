// Seed 000's first back-projection fix: a spotlight term with the proper cut-off, 0 behind the
// projector because the angle to its axis is over 90 degrees there. Written once in the subset
// GLSL and C++ share: projector.frag includes this file, and so does spot_math.hpp, which the
// tests check against the formula at hand-worked points.
//
// `d` runs from the projector to the surface point, `axis` is where it points (unit length).
// A spot fades from 1 at `halfAngle * (1 - falloff)` off its axis to 0 at `halfAngle`
// (smoothstep on the cosine); a parallel projector from 1 at `(1 - falloff) * extent` from its
// axis to 0 at `extent`, and gives 0 behind it. falloff 0 is off: 1 everywhere.
float spotFalloff(vec3 d, vec3 axis, int directional, float falloff, float halfAngle,
                  float extent) {
  if (falloff <= 0.0f) return 1.0f;
  float along = dot(d, axis);
  if (directional == 1) {
    if (along <= 0.0f) return 0.0f;
    float radial = length(d - along * axis) / extent;
    return 1.0f - smoothstep(1.0f - falloff, 1.0f, radial);
  }
  float cos_angle = along / max(length(d), 1e-6f);
  return smoothstep(cos(halfAngle), cos(halfAngle * (1.0f - falloff)), cos_angle);
}
