#version 330 core
// Slides 43-49: each vertex carries the plane of its triangle. Where that plane faces away
// from the light the vertex goes to infinity along the light's ray, w = 0 (the dark cap, and
// the far edge of a side quad); where it faces the light it stays (the light cap, the near
// edge). A side quad between two triangles that agree stays degenerate: only silhouette
// edges rasterize, found here, not on the CPU.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec4 aPlane;
layout(location = 2) in vec4 aOwner;
uniform mat4 uModel;
uniform mat4 uViewProjection;
uniform vec4 uLight;  // in the mesh's space: (position, 1), or (-direction, 0)
uniform int uDropLightCap;
uniform int uDropDarkCap;
invariant gl_Position;
void main() {
  bool lit = dot(aPlane, uLight) > 0.0;
  vec4 p = lit ? vec4(aPosition, 1.0) : vec4(aPosition * uLight.w - uLight.xyz, 0.0);
  bool dropped = lit ? uDropLightCap == 1 : uDropDarkCap == 1;
#if VOLUME_GEOMETRY == VOLUME_GEOMETRY_PER_TRIANGLE
  dropped = dropped || dot(aOwner, uLight) <= 0.0;  // a triangle facing away casts no volume
#endif
  // Every vertex of a dropped triangle lands on one point: nothing rasterizes.
  if (dropped) p = vec4(0.0, 0.0, 0.0, 1.0);
  gl_Position = uViewProjection * (uModel * p);
}
