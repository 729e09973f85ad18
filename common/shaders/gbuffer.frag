#version 330 core
in vec3 vWorld;
uniform int uObject;
uniform mat4 uLightViewProjection;  // pixels outside this frustum (near to far) are not counted
uniform int uHasLightFrustum;
layout(location = 0) out vec4 outPosition;  // xyz world, w object (or -1: not counted)
layout(location = 1) out vec4 outNormal;
void main() {
  // The geometric normal of the triangle, not the interpolated one: truth rays leave the
  // true surface.
  vec3 n = normalize(cross(dFdx(vWorld), dFdy(vWorld)));
  float object = float(uObject);
  // A surface seen from behind (the underside of the floor; a solid's inside is culled before
  // it gets here) is not counted: the eye is where no lesson's picture means anything.
  if (!gl_FrontFacing) object = -1.0;
  if (uHasLightFrustum == 1) {
    // Beside it, before its near or beyond its far plane the map holds nothing of the scene,
    // whatever a lesson then answers (lessons 03-08 call it lit unless something in the map
    // covers it): not counted.
    vec4 c = uLightViewProjection * vec4(vWorld, 1.0);
    if (c.w <= 0.0 || any(greaterThan(abs(c.xyz), vec3(c.w)))) object = -1.0;
  }
  outPosition = vec4(vWorld, object);
  outNormal = vec4(n, 0.0);
}
