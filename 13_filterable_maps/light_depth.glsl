// The depth both passes agree on: the distance along the light's axis, from its near plane
// (0) to its far plane (1). Linear, for a spot light too: the moments of a window depth,
// crowded near 1, would leave the variance no bits (Donnelly and Lauritzen store linear depth).
uniform vec3 uMapLightPos;
uniform vec3 uMapLightDir;  // unit, from the light into the scene
uniform float uNear;
uniform float uFar;
float lightDepth01(vec3 world) {
  return (dot(world - uMapLightPos, uMapLightDir) - uNear) / (uFar - uNear);
}
