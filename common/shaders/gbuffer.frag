#version 330 core
in vec3 vWorld;
uniform int uObject;
uniform mat4 uLightViewProjection;  // pixels outside this frustum (near to far) are not counted
uniform int uHasLightFrustum;
uniform int uHasLightReach;  // an omni light's reach (Frame::LightReach): outside it, not counted
uniform vec3 uReachLight;
uniform vec3 uReach;  // near along the face's axis, far, far along the axis (1) or |v| (0)
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
  if (uHasLightReach == 1) {
    // A cube holds nothing before its near plane or from its far on (lesson 11 calls it lit
    // there, in each store's own measure of far): not counted, as beyond a map's frustum.
    vec3 v = vWorld - uReachLight;
    float major = max(abs(v.x), max(abs(v.y), abs(v.z)));
    float reach = uReach.z > 0.5 ? major : length(v);
    if (major < uReach.x || reach >= uReach.y) object = -1.0;
  }
  outPosition = vec4(vWorld, object);
  outNormal = vec4(n, 0.0);
}
