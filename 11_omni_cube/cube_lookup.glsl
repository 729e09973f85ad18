// The cube map's arithmetic, as cube_math.hpp has it in C++ (tested there): which face a
// direction from the light reads, the distance along that face's axis, and the reference a
// fragment compares with the stored value, in either store.
uniform float uCubeNear;
uniform float uCubeFar;
uniform float uCubeSize;  // texels along a face's side

int majorFace(vec3 v) {
  vec3 a = abs(v);
  if (a.x >= a.y && a.x >= a.z) return v.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return v.y >= 0.0 ? 2 : 3;
  return v.z >= 0.0 ? 4 : 5;
}

float majorDistance(vec3 v) {
  vec3 a = abs(v);
  return max(a.x, max(a.y, a.z));
}

// faceProjection's window depth for a point z along the face's axis.
float majorDepth(float z) {
  return uCubeFar * (z - uCubeNear) / (z * (uCubeFar - uCubeNear));
}

// One texel's world size at distance z along a face's axis.
float texelWorldSize(float z) {
  return 2.0 * z / uCubeSize;
}
